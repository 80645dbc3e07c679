#pragma once
// The wave grid as the water's shaders read it: per cell its slope (dh/dx, dh/dz) and
// Laplacian, from central differences (one-sided on the border), and its height (the
// surface's vertices), with a box-filtered mip chain, so that the sea's shading reads one
// texel at the pixel's footprint. Derived on the CPU from the sim's heights: a few
// hundred microseconds, where a slope pass and glGenerateMipmap cost llvmpipe
// milliseconds a frame.
#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "effects/water/WaterView.h"

namespace effects {

class WaveGridMips {
public:
    // Recomputes every level from the grid (size >= 1). Texel (i, j) of level 0 is
    // (dh/dx, dh/dz, Laplacian, height) of cell (i, j); level k + 1 averages 2x2 texels
    // of level k (the last row or column repeated where level k's size is odd).
    void derive(const WaveHeights& grid);

    int levels() const { return int(level_offsets_.size()); }
    int level_size(int level) const { return std::max(grid_size_ >> level, 1); }
    // Rows of texels, row j = cell row j (GL's upload order, row 0 first).
    std::span<const glm::vec4> level(int level) const;

private:
    int grid_size_ = 0;
    std::vector<size_t> level_offsets_;
    std::vector<glm::vec4> texels_;
};

}  // namespace effects
