#include "effects/water/SurfaceLod.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace effects {

namespace {

// Gribb & Hartmann: the six clip planes of a view-projection matrix (normals inward).
std::array<glm::vec4, 6> frustum_planes(const glm::mat4& m) {
    glm::vec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]),
        r2(m[0][2], m[1][2], m[2][2], m[3][2]), r3(m[0][3], m[1][3], m[2][3], m[3][3]);
    return {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
}

bool box_outside(const std::array<glm::vec4, 6>& planes, glm::vec3 lo, glm::vec3 hi) {
    for (const glm::vec4& p : planes) {
        glm::vec3 far_corner(p.x >= 0.0f ? hi.x : lo.x, p.y >= 0.0f ? hi.y : lo.y, p.z >= 0.0f ? hi.z : lo.z);
        if (p.x * far_corner.x + p.y * far_corner.y + p.z * far_corner.z + p.w < 0.0f) return true;
    }
    return false;
}

}  // namespace

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
    const auto planes = frustum_planes(view.view_proj);
    for (int ty = 0; ty < n; ++ty)
        for (int tx = 0; tx < n; ++tx) {
            glm::vec3 lo, hi;
            bounds(tx, ty, lo, hi);
            if (box_outside(planes, lo, hi)) continue;
            int s = stride_at(tx, ty);
            glm::ivec4 edges(std::max(s, stride_at(tx, ty - 1)), std::max(s, stride_at(tx + 1, ty)),
                             std::max(s, stride_at(tx, ty + 1)), std::max(s, stride_at(tx - 1, ty)));
            draws.push_back({{tx, ty}, s, edges});
        }
    return draws;
}

}  // namespace effects
