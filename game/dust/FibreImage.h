#pragma once
// A binarised photo (or drawing) of dust fibres, the input of the seed's fibre
// statistics: black pixels are fibre, white are background. An image may stack several
// equal slices vertically, one per shell layer, to give the up/down directions too.
// Shared by the level loader and `spindrift fibres`.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "effects/dust/FibreDirections.h"
#include "game/capture/Image.h"

namespace game {

struct FibreImageError : std::runtime_error {
    using runtime_error::runtime_error;
};

struct FibreImage {
    int width = 0, slice_height = 0, slices = 1;
    std::vector<uint8_t> fibre;  // 1 where black, rows top-down, slices one after another
};

inline constexpr int kMaxFibreSlices = 16;

// Checks that every pixel is black (grey <= 32) or white (>= 223) and that there are
// fibre pixels and background; throws FibreImageError naming `what` (the file) and
// the first offending pixel otherwise.
FibreImage binarised_fibres(const ImageRGBA8& image, int slices, const std::string& what);
// Reads the file (a PNG, read_png), then binarised_fibres.
FibreImage read_fibre_image(const std::filesystem::path& file, int slices);
// The direction table; throws FibreImageError when no two fibre pixels touch.
effects::FibreDirections fibre_directions(const FibreImage& image, const std::string& what);
// read_fibre_image, then fibre_directions: the level loader's fibre reader.
effects::FibreDirections read_fibre_directions(const std::filesystem::path& file, int slices);

// Draws the kind of image the harbour ships (levels/harbour/dust_fibres.png): fibres as
// smooth random curves, one pixel wide, crossing between slices now and then. From
// a seed, so it can be made again.
ImageRGBA8 draw_fibre_image(int width, int slices, int fibres, uint64_t seed);

}  // namespace game
