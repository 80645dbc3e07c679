#include "effects/water/WaterSurfaceMesh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace effects {

namespace {

bool power_of_two(int v) { return v > 0 && (v & (v - 1)) == 0; }

float signed_area_xz(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Where a vertex of the frame lies, for winding: lattice or world coordinates.
glm::vec2 frame_xz(const WaterSurfaceMesh& m, const SurfaceVertex& v) {
    return v.explicit_xz > 0.0f ? v.coord : lattice_xz(m.lattice, v.coord);
}

// Adds a triangle wound counter-clockwise in xz whatever order it came in.
void add_triangle(WaterSurfaceMesh& m, glm::vec2 pa, glm::vec2 pb, glm::vec2 pc, uint32_t a, uint32_t b, uint32_t c) {
    if (signed_area_xz(pa, pb, pc) < 0.0f) std::swap(b, c);
    m.indices.insert(m.indices.end(), {a, b, c});
}

uint32_t add_vertex(WaterSurfaceMesh& m, glm::vec2 coord, bool explicit_xz) {
    m.vertices.push_back({coord, explicit_xz ? 1.0f : 0.0f, 0.0f});
    return uint32_t(m.vertices.size() - 1);
}

void add_frame_triangle(WaterSurfaceMesh& m, uint32_t a, uint32_t b, uint32_t c) {
    add_triangle(m, frame_xz(m, m.vertices[a]), frame_xz(m, m.vertices[b]), frame_xz(m, m.vertices[c]), a, b, c);
}

}  // namespace

WaterSurfaceMesh make_water_surface_mesh(const WaveHeights* grid, int max_lattice_cells, int tile_cells,
                                         float min_half_extent_m) {
    if (!power_of_two(max_lattice_cells) || !power_of_two(tile_cells))
        throw std::invalid_argument("water surface mesh: lattice and tile cells must be powers of two, got " +
                                    std::to_string(max_lattice_cells) + " and " + std::to_string(tile_cells));
    if (!(min_half_extent_m > 0.0f)) throw std::invalid_argument("water surface mesh: extent must be positive");
    WaterSurfaceMesh m;
    float e = min_half_extent_m;
    if (!grid) {
        m.half_extent_m = e;
        m.frame.first = 0;
        for (glm::vec2 p : {glm::vec2(-e, -e), glm::vec2(e, -e), glm::vec2(e, e), glm::vec2(-e, e)}) add_vertex(m, p, true);
        add_frame_triangle(m, 0, 1, 2);
        add_frame_triangle(m, 0, 2, 3);
        m.frame.count = uint32_t(m.indices.size());
        return m;
    }
    const glm::vec2 lo = grid->origin_xz, hi = grid->far_corner_xz();
    // The frame must enclose the grid with room to spare.
    e = std::max(e, 2.0f * std::max({std::abs(lo.x), std::abs(lo.y), std::abs(hi.x), std::abs(hi.y)}));
    m.half_extent_m = e;

    LatticeLayout& l = m.lattice;
    l.lattice_cells = 1;
    while (l.lattice_cells < grid->size - 1 && l.lattice_cells < max_lattice_cells) l.lattice_cells *= 2;
    l.tile_cells = std::min(tile_cells, l.lattice_cells);
    l.tiles_per_side = l.lattice_cells / l.tile_cells;
    l.origin_xz = lo;
    l.cell_m = (hi.x - lo.x) / float(l.lattice_cells);

    // One tile's vertices in tile-local lattice coordinates, and its triangles at each stride.
    const int t = l.tile_cells;
    for (int j = 0; j <= t; ++j)
        for (int i = 0; i <= t; ++i) add_vertex(m, glm::vec2(i, j), false);
    auto at = [t](int i, int j) { return uint32_t(j * (t + 1) + i); };
    for (int s = 1; s <= t; s *= 2) {
        IndexRange range{uint32_t(m.indices.size()), 0};
        for (int j = 0; j < t; j += s)
            for (int i = 0; i < t; i += s) {
                glm::vec2 a(i, j), b(i + s, j), c(i + s, j + s), d(i, j + s);
                add_triangle(m, a, b, c, at(i, j), at(i + s, j), at(i + s, j + s));
                add_triangle(m, a, c, d, at(i, j), at(i + s, j + s), at(i, j + s));
            }
        range.count = uint32_t(m.indices.size()) - range.first;
        m.tile_strides.push_back(range);
    }

    // The frame: four trapezoids from the lattice's sides to the outer square's, each a
    // strip of one quad per tile; its inner ring is the lattice border at the tile corners.
    m.frame.first = uint32_t(m.indices.size());
    const int n = l.tiles_per_side;
    struct Side {
        glm::ivec2 start, step;  // along the lattice border, in tiles
        glm::vec2 outer_a, outer_b;
    };
    const Side sides[4] = {
        {{0, 0}, {1, 0}, {-e, -e}, {e, -e}},
        {{n, 0}, {0, 1}, {e, -e}, {e, e}},
        {{n, n}, {-1, 0}, {e, e}, {-e, e}},
        {{0, n}, {0, -1}, {-e, e}, {-e, -e}},
    };
    for (const Side& s : sides) {
        const uint32_t first = uint32_t(m.vertices.size());
        for (int k = 0; k <= n; ++k) {
            glm::ivec2 tile = s.start + s.step * k;
            add_vertex(m, glm::vec2(tile * t), false);
            add_vertex(m, s.outer_a + (float(k) / float(n)) * (s.outer_b - s.outer_a), true);
        }
        for (int k = 0; k < n; ++k) {
            uint32_t in0 = first + uint32_t(2 * k), out0 = in0 + 1, in1 = in0 + 2, out1 = in0 + 3;
            add_frame_triangle(m, in0, in1, out1);
            add_frame_triangle(m, in0, out1, out0);
        }
    }
    m.frame.count = uint32_t(m.indices.size()) - m.frame.first;
    return m;
}

}  // namespace effects
