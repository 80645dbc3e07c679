#pragma once
// The sea surface as static geometry: a lattice over the wave grid, cut into square
// tiles that can each be drawn at strides 1, 2, 4 ... (coarser far from the eye, see
// SurfaceLod.h), and a flat frame from the lattice's border out to the horizon. The
// vertex shader places lattice vertices from integer lattice coordinates and lifts
// them by the grid's heights; the lattice's border stays at rest, where the frame
// meets it at the tile corners.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "effects/water/WaterView.h"

namespace effects {

struct SurfaceVertex {
    glm::vec2 coord{0.0f};   // lattice coordinates (tile-local for tiles), or world xz if explicit_xz
    float explicit_xz = 0.0f;  // 1 on the frame's outer ring
    float unused = 0.0f;
};

struct IndexRange {
    uint32_t first = 0;  // in indices
    uint32_t count = 0;
};

// lattice_cells x lattice_cells cells over the grid's rectangle in tiles of tile_cells.
struct LatticeLayout {
    int lattice_cells = 0;  // 0 without a grid
    int tile_cells = 0;
    int tiles_per_side = 0;
    glm::vec2 origin_xz{0.0f};
    float cell_m = 0.0f;
};

struct WaterSurfaceMesh {
    LatticeLayout lattice;
    std::vector<SurfaceVertex> vertices;  // one tile's (tile_cells+1)^2 local vertices, then the frame's
    std::vector<uint32_t> indices;        // triangles, counter-clockwise seen from above
    std::vector<IndexRange> tile_strides; // [k]: one tile at stride 2^k, k = 0 .. log2(tile_cells)
    IndexRange frame;                     // the frame, or the whole flat sea without a grid
    float half_extent_m = 0.0f;           // the outer square reaches +-this in x and z
};

// With a grid: a lattice of min(max_lattice_cells, the grid's cells rounded up to a
// power of two) cells per side in tiles of at most tile_cells (both powers of two),
// and the frame out to at least +-min_half_extent_m. Without a grid: one flat square.
// Throws std::invalid_argument for sizes that are not powers of two or a bad extent.
WaterSurfaceMesh make_water_surface_mesh(const WaveHeights* grid, int max_lattice_cells, int tile_cells,
                                         float min_half_extent_m);

// Where lattice coordinate g stands in world xz (as the vertex shader computes it).
inline glm::vec2 lattice_xz(const LatticeLayout& l, glm::vec2 g) { return l.origin_xz + g * l.cell_m; }

}  // namespace effects
