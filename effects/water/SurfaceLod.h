#pragma once
// Which stride each lattice tile is drawn at: fine near the eye, coarser where its
// cells shrink to a few pixels (tiny triangles are what a software rasteriser pays
// most for), tiles outside the view skipped. A tile edge shared with a coarser tile,
// or lying on the lattice border, is drawn at the coarser stride by both sides (the
// vertex shader folds the finer side's extra vertices onto it), so no cracks open.
#include <array>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "effects/water/WaterSurfaceMesh.h"

namespace effects {

struct LodView {
    glm::mat4 view_proj{1.0f};
    glm::vec3 eye{0.0f};
    float pixels_per_radian = 500.0f;  // viewport height / (2 tan(fov_y / 2))
    float target_cell_px = 12.0f;      // aim for triangles about this many pixels across
    float min_y = -1.0f, max_y = 1.0f; // the surface's height range (world y)
};

struct TileDraw {
    glm::ivec2 tile{0};       // in tiles from the lattice origin
    int stride = 1;           // in lattice cells, a power of two up to tile_cells
    glm::ivec4 edge_stride{1};// effective stride on the -z, +x, +z, -x edges (>= stride)
};

// The tiles to draw, in row order.
std::vector<TileDraw> plan_tiles(const LatticeLayout& lattice, const LodView& view);

}  // namespace effects
