#include "effects/water/SurfaceLod.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "effects/scene/Frustum.h"

namespace effects {

std::vector<TileDraw> plan_tiles(const LatticeLayout& l, const LodView& view) {
    std::vector<TileDraw> draws;
    const int n = l.tiles_per_side;
    if (n <= 0) return draws;
    const float tile_m = l.cell_m * float(l.tile_cells);
    auto bounds = [&](int tx, int ty, glm::vec3& lo, glm::vec3& hi) {
        glm::vec2 a = lattice_xz(l, glm::vec2(tx, ty) * float(l.tile_cells));
        lo = glm::vec3(a.x, view.min_y, a.y);
        hi = glm::vec3(a.x + tile_m, view.max_y, a.y + tile_m);
    };
    // Stride per tile from the nearest point's distance: the coarsest power of two
    // whose cells still project to no more than the target size.
    std::vector<int> stride(size_t(n) * size_t(n));
    for (int ty = 0; ty < n; ++ty)
        for (int tx = 0; tx < n; ++tx) {
            glm::vec3 lo, hi;
            bounds(tx, ty, lo, hi);
            float dist = glm::length(glm::clamp(view.eye, lo, hi) - view.eye);
            float cell_px = l.cell_m * view.pixels_per_radian / std::max(dist, 1e-3f);
            int s = 1;
            while (s < l.tile_cells && cell_px * float(s * 2) <= view.target_cell_px) s *= 2;
            stride[size_t(ty * n + tx)] = s;
        }
    auto stride_at = [&](int tx, int ty) {
        // Outside the lattice the frame meets it at tile corners only.
        if (tx < 0 || ty < 0 || tx >= n || ty >= n) return l.tile_cells;
        return stride[size_t(ty * n + tx)];
    };
    const Frustum frustum(view.view_proj);
    for (int ty = 0; ty < n; ++ty)
        for (int tx = 0; tx < n; ++tx) {
            glm::vec3 lo, hi;
            bounds(tx, ty, lo, hi);
            if (frustum.outside(lo, hi)) continue;
            int s = stride_at(tx, ty);
            glm::ivec4 edges(std::max(s, stride_at(tx, ty - 1)), std::max(s, stride_at(tx + 1, ty)),
                             std::max(s, stride_at(tx, ty + 1)), std::max(s, stride_at(tx - 1, ty)));
            draws.push_back({{tx, ty}, s, edges});
        }
    return draws;
}

}  // namespace effects
