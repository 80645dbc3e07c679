#pragma once
// The growth-direction statistics of dust fibres (seed §2, fig. 1): at each fibre
// pixel of a binarised fibre image, which of its 26 neighbours in a 3x3x3
// neighbourhood (in-plane, and one shell layer up or down) are fibre too. Images
// may hold several slices stacked vertically, one per layer; with one slice only the
// 8 in-plane directions occur.
#include <array>
#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

namespace effects {

struct FibreDirections {
    static constexpr int kCount = 26;
    // Probability of each neighbour offset (see offset()); sums to 1 once analysed.
    std::array<float, kCount> probability{};

    // (dx, dy, dlayer) of direction k: x right, y down the image, layer up.
    static glm::ivec3 offset(int k);
    bool empty() const;
};

// Counts neighbour pairs over `fibre` (width x slice_height x slices, slices stacked,
// rows top-down; non-zero = fibre). Neighbours outside the image do not count.
// Throws std::invalid_argument for a size that does not match or an image in which no
// two fibre pixels touch.
FibreDirections analyse_fibre_pixels(int width, int slice_height, int slices, std::span<const uint8_t> fibre);

}  // namespace effects
