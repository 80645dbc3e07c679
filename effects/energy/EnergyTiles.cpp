#include "effects/energy/EnergyTiles.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

namespace effects {

namespace {

struct TileRect {
    int x0, y0, x1, y1;  // inclusive tile range
};

// The tiles the segment can cover: the projection of the box around its capsule of
// influence (R around the axis, R beyond each end), all tiles when the box reaches
// the near plane (its projection is unbounded there).
TileRect cover(const Camera& cam, const sim::EnergySegment& s, int tiles_x, int tiles_y, int width, int height) {
    const TileRect all{0, 0, tiles_x - 1, tiles_y - 1};
    const glm::vec3 d = s.direction;
    const glm::vec3 side = glm::normalize(std::fabs(d.y) < 0.9f ? glm::cross(d, glm::vec3(0, 1, 0))
                                                                 : glm::cross(d, glm::vec3(1, 0, 0)));
    const glm::vec3 up = glm::cross(side, d);
    const float r = s.radius_m;
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (int c = 0; c < 8; ++c) {
        glm::vec3 corner = s.start + d * (c & 1 ? s.length_m + r : -r) + side * (c & 2 ? r : -r) + up * (c & 4 ? r : -r);
        glm::vec4 clip = cam.view_proj * glm::vec4(corner, 1.0f);
        if (clip.w <= cam.near_m) return all;
        glm::vec2 ndc = glm::vec2(clip) / clip.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    if (hi.x < -1.0f || hi.y < -1.0f || lo.x > 1.0f || lo.y > 1.0f) return {0, 0, -1, -1};
    auto tile = [](float ndc, int pixels, int tiles) {
        float px = (std::clamp(ndc, -1.0f, 1.0f) * 0.5f + 0.5f) * float(pixels);
        return std::clamp(int(px) / EnergyTileGrid::kTilePx, 0, tiles - 1);
    };
    return {tile(lo.x, width, tiles_x), tile(lo.y, height, tiles_y), tile(hi.x, width, tiles_x),
            tile(hi.y, height, tiles_y)};
}

}  // namespace

void bin_energy_segments(const Camera& camera, int width, int height, std::span<const sim::EnergySegment> segments,
                         bool cull, EnergyTileGrid& grid) {
    grid.tiles.clear();
    grid.indices.clear();
    if (segments.empty()) return;
    const int tiles_x = (width + EnergyTileGrid::kTilePx - 1) / EnergyTileGrid::kTilePx;
    const int tiles_y = (height + EnergyTileGrid::kTilePx - 1) / EnergyTileGrid::kTilePx;
    // Count per tile, then fill: two passes over the segments' rectangles.
    std::vector<TileRect> rects(segments.size());
    std::vector<uint32_t> count(size_t(tiles_x) * size_t(tiles_y), 0);
    for (size_t i = 0; i < segments.size(); ++i) {
        rects[i] = cull ? cover(camera, segments[i], tiles_x, tiles_y, width, height)
                        : TileRect{0, 0, tiles_x - 1, tiles_y - 1};
        for (int y = rects[i].y0; y <= rects[i].y1; ++y)
            for (int x = rects[i].x0; x <= rects[i].x1; ++x) ++count[size_t(y) * size_t(tiles_x) + size_t(x)];
    }
    std::vector<uint32_t> first(count.size(), 0);
    uint32_t total = 0;
    for (int y = 0; y < tiles_y; ++y)
        for (int x = 0; x < tiles_x; ++x) {
            size_t t = size_t(y) * size_t(tiles_x) + size_t(x);
            if (count[t] == 0) continue;
            first[t] = total;
            grid.tiles.push_back({uint32_t(x), uint32_t(y), total, count[t]});
            total += count[t];
        }
    grid.indices.resize(total);
    std::vector<uint32_t> filled(count.size(), 0);
    for (size_t i = 0; i < segments.size(); ++i)
        for (int y = rects[i].y0; y <= rects[i].y1; ++y)
            for (int x = rects[i].x0; x <= rects[i].x1; ++x) {
                size_t t = size_t(y) * size_t(tiles_x) + size_t(x);
                grid.indices[first[t] + filled[t]++] = uint32_t(i);
            }
}

}  // namespace effects
