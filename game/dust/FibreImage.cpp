#include "game/dust/FibreImage.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "game/capture/ImageFiles.h"
#include "sim/core/Rng.h"

namespace game {

FibreImage binarised_fibres(const ImageRGBA8& image, int slices, const std::string& what) {
    if (slices < 1 || slices > kMaxFibreSlices)
        throw FibreImageError(what + ": slices must be 1.." + std::to_string(kMaxFibreSlices) + ", not " +
                              std::to_string(slices));
    if (image.width < 4 || image.height < 4)
        throw FibreImageError(what + ": image is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                              ", too small to hold fibres (at least 4x4)");
    if (image.height % slices != 0)
        throw FibreImageError(what + ": height " + std::to_string(image.height) + " does not split into " +
                              std::to_string(slices) + " equal slices");
    FibreImage out;
    out.width = image.width;
    out.slice_height = image.height / slices;
    out.slices = slices;
    out.fibre.resize(size_t(image.width) * size_t(image.height));
    size_t black = 0;
    for (size_t i = 0; i < out.fibre.size(); ++i) {
        const uint8_t* px = &image.pixels[i * 4];
        int grey = (int(px[0]) + int(px[1]) + int(px[2])) / 3;
        if (grey > 32 && grey < 223)
            throw FibreImageError(what + ": not a binarised image: pixel (" + std::to_string(i % size_t(image.width)) +
                                  ", " + std::to_string(i / size_t(image.width)) + ") has grey level " +
                                  std::to_string(grey) + " (fibres must be black, the rest white)");
        out.fibre[i] = grey <= 32;
        black += out.fibre[i];
    }
    if (black == 0) throw FibreImageError(what + ": no fibres: the image has no black pixels");
    if (black == out.fibre.size()) throw FibreImageError(what + ": no background: every pixel is black");
    return out;
}

FibreImage read_fibre_image(const std::filesystem::path& file, int slices) {
    ImageRGBA8 image;
    try {
        image = read_png(file);
    } catch (const std::exception& e) {
        throw FibreImageError(std::string("fibre image: ") + e.what());
    }
    return binarised_fibres(image, slices, file.string());
}

effects::FibreDirections fibre_directions(const FibreImage& image, const std::string& what) {
    try {
        return effects::analyse_fibre_pixels(image.width, image.slice_height, image.slices, image.fibre);
    } catch (const std::invalid_argument& e) {
        throw FibreImageError(what + ": " + e.what());
    }
}

effects::FibreDirections read_fibre_directions(const std::filesystem::path& file, int slices) {
    return fibre_directions(read_fibre_image(file, slices), file.string());
}

ImageRGBA8 draw_fibre_image(int width, int slices, int fibres, uint64_t seed) {
    ImageRGBA8 img;
    img.width = width;
    img.height = width * slices;
    img.pixels.assign(size_t(img.width) * size_t(img.height) * 4, 255);
    sim::Rng rng(seed, 0xf1b7e5u);
    for (int f = 0; f < fibres; ++f) {
        float x = rng.unit() * float(width), y = rng.unit() * float(width);
        int slice = int(rng.below(uint32_t(slices)));
        float angle = rng.range(0.0f, 6.2831853f), turn = 0.0f;
        const int length = 20 + int(rng.below(uint32_t(width)));
        for (int s = 0; s < length; ++s) {
            // A slowly wandering curvature with the odd sharp kink: lint, not hair.
            turn = 0.9f * turn + rng.range(-0.05f, 0.05f);
            angle += turn + (rng.unit() < 0.02f ? rng.range(-1.5f, 1.5f) : 0.0f);
            x += std::cos(angle);
            y += std::sin(angle);
            if (rng.unit() < 0.03f) slice = std::clamp(slice + (rng.unit() < 0.5f ? -1 : 1), 0, slices - 1);
            int px = ((int(std::floor(x)) % width) + width) % width, py = ((int(std::floor(y)) % width) + width) % width;
            size_t i = (size_t(slice * width + py) * size_t(width) + size_t(px)) * 4;
            img.pixels[i] = img.pixels[i + 1] = img.pixels[i + 2] = 0;
        }
    }
    return img;
}

}  // namespace game
