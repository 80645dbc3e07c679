#include "effects/rain/DropTiles.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace effects {

DropTiles drops_by_tile(std::span<const RainMetaball> drops, glm::vec2 glass_size_m, int width, int height,
                        float radius_scale, float threshold) {
    constexpr int kTile = DropTiles::kTexels;
    DropTiles t;
    t.cols = (width + kTile - 1) / kTile;
    t.rows = (height + kTile - 1) / kTile;
    const glm::vec2 texel = glass_size_m / glm::vec2(float(width), float(height));
    const glm::vec2 tile_m = texel * float(kTile);
    // (tile, drop) for every drop reaching a tile's texel centres, visiting only the
    // tiles its reach square overlaps (a tile of slack against rounding), in drop order.
    std::vector<glm::uvec2> pairs;
    pairs.reserve(drops.size() * 8);
    std::vector<uint32_t> count(size_t(t.cols) * size_t(t.rows), 0);
    std::vector<float> peak(count.size(), 0.0f);  // sum of each drop's densest point in the tile
    // The offset from a drop to a tile's texel-centre box is separable: per column, per row.
    const auto box_offset = [&](float c, int tile, int texels, float texel_m) {
        const float lo = (float(tile * kTile) + 0.5f) * texel_m;
        const float hi = (float(std::min((tile + 1) * kTile, texels)) - 0.5f) * texel_m;
        return c - std::clamp(c, lo, hi);
    };
    std::vector<float> ex2(size_t(t.cols)), ey2(size_t(t.rows));
    for (size_t k = 0; k < drops.size(); ++k) {
        const RainMetaball& d = drops[k];
        const float r = d.radius_m * radius_scale, reach = kMetaballReach * r, inv_r2 = 1.0f / (r * r);
        const glm::ivec2 lo = glm::max(glm::ivec2(glm::floor((d.centre_m - reach) / tile_m)) - 1, glm::ivec2(0));
        const glm::ivec2 hi = glm::min(glm::ivec2(glm::floor((d.centre_m + reach) / tile_m)) + 1, glm::ivec2(t.cols - 1, t.rows - 1));
        for (int ti = lo.x; ti <= hi.x; ++ti) {
            const float e = box_offset(d.centre_m.x, ti, width, texel.x);
            ex2[size_t(ti)] = e * e;
        }
        for (int tj = lo.y; tj <= hi.y; ++tj) {
            const float e = box_offset(d.centre_m.y, tj, height, texel.y);
            ey2[size_t(tj)] = e * e;
        }
        for (int tj = lo.y; tj <= hi.y; ++tj)
            for (int ti = lo.x; ti <= hi.x; ++ti) {
                const float e2 = ex2[size_t(ti)] + ey2[size_t(tj)];
                if (e2 >= reach * reach) continue;
                const uint32_t tile = uint32_t(tj * t.cols + ti);
                pairs.emplace_back(tile, uint32_t(k));
                ++count[tile];
                const float q = e2 * inv_r2;
                peak[tile] += 1.0f / (1.0f + q * q);
            }
    }
    // Counting sort by tile; stable, so each tile keeps its drops in order.
    t.ranges.resize(count.size());
    uint32_t first = 0;
    for (size_t tile = 0; tile < count.size(); ++tile) {
        t.ranges[tile] = {first, 0u};
        // Half of T: far beyond the rounding of the GPU's half-float sums and profile.
        if (peak[tile] > 0.5f * threshold) {
            if (!t.wet.empty() && t.wet.back().x + t.wet.back().y == tile && tile % size_t(t.cols) != 0)
                ++t.wet.back().y;
            else
                t.wet.emplace_back(uint32_t(tile), 1u);
        }
        first += count[tile];
    }
    t.indices.resize(pairs.size());
    for (const glm::uvec2& p : pairs) t.indices[t.ranges[p.x].x + t.ranges[p.x].y++] = p.y;
    return t;
}

}  // namespace effects
