// spindrift fibres IMAGE [--slices N] [--layers OUT.png]
// spindrift fibres --draw OUT.png [--slices N] [--size N] [--count N] [--seed N]
// The seed's fibre analysis for anyone's image: prints the growth-direction table a
// binarised fibre image gives, and optionally the shell layers grown from it; or
// draws an example image like the one the harbour ships.
#include <cstdio>
#include <iostream>

#include "effects/dust/DustLook.h"
#include "effects/dust/FibreVolume.h"
#include "game/capture/ImageFiles.h"
#include "game/cli/Args.h"
#include "game/cli/Commands.h"
#include "game/cli/ExitCode.h"
#include "game/dust/FibreImage.h"

namespace game {

namespace {

// The grown layers side by side, fibres black on white, for a look.
ImageRGBA8 layer_strip(const effects::FibreVolume& v) {
    ImageRGBA8 img;
    img.width = v.size * v.layers;
    img.height = v.size;
    img.pixels.assign(size_t(img.width) * size_t(img.height) * 4, 255);
    for (int l = 0; l < v.layers; ++l)
        for (int y = 0; y < v.size; ++y)
            for (int x = 0; x < v.size; ++x)
                if (v.coverage(x, y, l)) {
                    size_t i = (size_t(y) * size_t(img.width) + size_t(l * v.size + x)) * 4;
                    img.pixels[i] = img.pixels[i + 1] = img.pixels[i + 2] = 0;
                }
    return img;
}

}  // namespace

int fibres_command(const std::vector<std::string>& argv) {
    Args args(argv, {"--slices", "--layers", "--draw", "--size", "--count", "--seed"}, {});
    const int slices = args.integer("--slices", 1, 1, kMaxFibreSlices);
    try {
        if (auto out = args.value("--draw")) {
            if (!args.positional().empty()) throw UsageError("fibres --draw takes no image argument");
            const int size = args.integer("--size", 128, 16, 2048);
            const int count = args.integer("--count", 60, 1, 100000);
            const int seed = args.integer("--seed", 4, 0, 1 << 30);
            write_png(*out, draw_fibre_image(size, slices, count, uint64_t(seed)));
            std::cout << "wrote " << *out << " (" << size << "x" << size * slices << ", " << slices << " slices)\n";
            return kExitOk;
        }
        if (args.positional().size() != 1) throw UsageError("fibres takes one image (or --draw OUT.png)");
        const std::string file = args.positional()[0];
        const effects::FibreDirections table = fibre_directions(read_fibre_image(file, slices), file);
        std::cout << "growth directions of " << file << " (dx, dy, dlayer: probability)\n";
        for (int k = 0; k < effects::FibreDirections::kCount; ++k) {
            glm::ivec3 d = effects::FibreDirections::offset(k);
            std::printf("  %+d %+d %+d: %.4f\n", d.x, d.y, d.z, double(table.probability[size_t(k)]));
        }
        std::fflush(stdout);
        if (auto out = args.value("--layers")) {
            effects::FibreVolume v = effects::grow_fibres(table, effects::dust_look(sim::DustKind::Dust).growth);
            write_png(*out, layer_strip(v));
            std::cout << "wrote " << *out << " (" << v.layers << " layers grown with the dust preset)\n";
        }
    } catch (const FibreImageError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    return kExitOk;
}

}  // namespace game
