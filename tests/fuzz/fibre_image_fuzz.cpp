// The fibre-image analysis on any pixels: a direction table that sums to 1, or one
// FibreImageError. The first bytes give the size and slice count, the rest are the
// RGBA pixels, repeated to fill the image (decoding the file is libpng's part).
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "game/dust/FibreImage.h"
#include "tests/fuzz/FuzzCheck.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 4) return 0;
    const int slices = 1 + data[2] % 4;
    game::ImageRGBA8 image;
    image.width = 1 + data[0];
    image.height = (1 + data[1]) * slices;
    const size_t count = size_t(image.width) * size_t(image.height) * 4;
    image.pixels.resize(count);
    for (size_t i = 0; i < count; ++i) image.pixels[i] = data[3 + i % (size - 3)];
    try {
        const game::FibreImage fibres = game::binarised_fibres(image, slices, "fuzz.png");
        FUZZ_CHECK(fibres.width == image.width && fibres.slices == slices);
        FUZZ_CHECK(fibres.fibre.size() == size_t(fibres.width) * size_t(fibres.slice_height) * size_t(slices));
        const effects::FibreDirections d = game::fibre_directions(fibres, "fuzz.png");
        float sum = 0.0f;
        for (float p : d.probability) {
            FUZZ_CHECK(std::isfinite(p) && p >= 0.0f && p <= 1.0f);
            sum += p;
        }
        FUZZ_CHECK(std::fabs(sum - 1.0f) < 1e-3f);
    } catch (const game::FibreImageError&) {
    }
    return 0;
}
