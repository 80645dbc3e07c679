#include "effects/energy/EnergyTiles.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

namespace effects {

namespace {

// A sphere's projection, in pixels: its exact bounding box (the tangent planes through
// the eye in x and in y), or why there is none.
enum class Projection { kBehind, kUnbounded, kBounded };

Projection project_sphere(const Camera& cam, glm::vec3 centre, float radius, int width, int height, glm::vec2& lo,
                          glm::vec2& hi) {
    const glm::vec4 v = cam.view * glm::vec4(centre, 1.0f);
    const float depth = -v.z;
    if (depth + radius <= 0.0f) return Projection::kBehind;  // wholly behind the eye
    if (depth - radius <= 1e-3f) return Projection::kUnbounded;  // reaches the eye's plane
    // The slopes x / depth of the two tangents to the circle (c, depth) of this radius.
    auto slopes = [&](float c) {
        const float root = radius * std::sqrt(c * c + depth * depth - radius * radius);
        const float denom = depth * depth - radius * radius;
        return glm::vec2(c * depth - root, c * depth + root) / denom;
    };
    const glm::vec2 sx = slopes(v.x) * cam.proj[0][0], sy = slopes(v.y) * cam.proj[1][1];  // NDC
    lo = (glm::vec2(sx.x, sy.x) * 0.5f + 0.5f) * glm::vec2(float(width), float(height));
    hi = (glm::vec2(sx.y, sy.y) * 0.5f + 0.5f) * glm::vec2(float(width), float(height));
    return Projection::kBounded;
}

// Where a segment's field can show: its capsule of influence (R around the axis and
// beyond both ends) is the hull of its two end spheres, so its projection is the hull
// of theirs, inside the hull of the circles around their bounding boxes and so within
// the larger circle's radius of the segment joining the boxes' centres.
struct Footprint {
    enum { kNone, kAll, kCapsule } kind = kNone;
    glm::vec2 a{0.0f}, b{0.0f};  // pixels
    float radius = 0.0f;
    glm::vec2 lo{0.0f}, hi{0.0f};  // the bounding box of both spheres' boxes
};

Footprint footprint(const Camera& cam, const sim::EnergySegment& s, int width, int height) {
    Footprint f;
    glm::vec2 lo[2], hi[2];
    const Projection p0 = project_sphere(cam, s.start, s.radius_m, width, height, lo[0], hi[0]);
    const Projection p1 =
        project_sphere(cam, s.start + s.direction * s.length_m, s.radius_m, width, height, lo[1], hi[1]);
    if (p0 == Projection::kBehind && p1 == Projection::kBehind) return f;
    if (p0 != Projection::kBounded || p1 != Projection::kBounded) {
        f.kind = Footprint::kAll;
        return f;
    }
    f.kind = Footprint::kCapsule;
    f.a = 0.5f * (lo[0] + hi[0]);
    f.b = 0.5f * (lo[1] + hi[1]);
    f.radius = 0.5f * std::max(glm::length(hi[0] - lo[0]), glm::length(hi[1] - lo[1]));
    f.lo = glm::min(lo[0], lo[1]);
    f.hi = glm::max(hi[0], hi[1]);
    return f;
}

float distance_to_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + t * ab));
}

// Between the segment a-b and the box [lo, hi]: zero where they meet, else the least of
// the endpoints' distances to the box and the corners' distances to the segment.
float distance_to_box(glm::vec2 a, glm::vec2 b, glm::vec2 lo, glm::vec2 hi) {
    // Clip the segment a + t (b - a), t in [0, 1], to the box's slabs.
    float t0 = 0.0f, t1 = 1.0f;
    const glm::vec2 ab = b - a;
    for (int k = 0; k < 2; ++k) {
        if (ab[k] == 0.0f) {
            if (a[k] < lo[k] || a[k] > hi[k]) t1 = -1.0f;
            continue;
        }
        float u0 = (lo[k] - a[k]) / ab[k], u1 = (hi[k] - a[k]) / ab[k];
        if (u0 > u1) std::swap(u0, u1);
        t0 = std::max(t0, u0);
        t1 = std::min(t1, u1);
    }
    if (t0 <= t1) return 0.0f;
    auto to_box = [&](glm::vec2 p) { return glm::length(glm::max(glm::max(lo - p, p - hi), glm::vec2(0.0f))); };
    float d = std::min(to_box(a), to_box(b));
    for (glm::vec2 corner : {lo, hi, glm::vec2(lo.x, hi.y), glm::vec2(hi.x, lo.y)})
        d = std::min(d, distance_to_segment(corner, a, b));
    return d;
}

}  // namespace

void bin_energy_segments(const Camera& camera, int width, int height, std::span<const sim::EnergySegment> segments,
                         bool cull, EnergyTileGrid& grid) {
    grid.tiles.clear();
    grid.indices.clear();
    if (segments.empty()) return;
    constexpr int kTile = EnergyTileGrid::kTilePx;
    const int tiles_x = (width + kTile - 1) / kTile, tiles_y = (height + kTile - 1) / kTile;
    // (tile, segment) pairs in segment order, then counted into per-tile lists: each
    // tile's segments stay in index order, so H sums them as without culling.
    std::vector<glm::uvec2> pairs;
    std::vector<uint32_t> count(size_t(tiles_x) * size_t(tiles_y), 0);
    auto add = [&](int x, int y, size_t i) {
        const size_t t = size_t(y) * size_t(tiles_x) + size_t(x);
        pairs.push_back({uint32_t(t), uint32_t(i)});
        ++count[t];
    };
    for (size_t i = 0; i < segments.size(); ++i) {
        const Footprint f = cull ? footprint(camera, segments[i], width, height) : Footprint{Footprint::kAll};
        if (f.kind == Footprint::kNone) continue;
        if (f.kind == Footprint::kAll) {
            for (int y = 0; y < tiles_y; ++y)
                for (int x = 0; x < tiles_x; ++x) add(x, y, i);
            continue;
        }
        if (f.hi.x < 0.0f || f.hi.y < 0.0f || f.lo.x > float(width) || f.lo.y > float(height)) continue;
        const int x0 = std::clamp(int(std::floor(f.lo.x)) / kTile, 0, tiles_x - 1);
        const int y0 = std::clamp(int(std::floor(f.lo.y)) / kTile, 0, tiles_y - 1);
        const int x1 = std::clamp(int(std::floor(f.hi.x)) / kTile, 0, tiles_x - 1);
        const int y1 = std::clamp(int(std::floor(f.hi.y)) / kTile, 0, tiles_y - 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 tile_lo(float(x * kTile), float(y * kTile));
                if (distance_to_box(f.a, f.b, tile_lo, tile_lo + float(kTile)) <= f.radius) add(x, y, i);
            }
    }
    std::vector<uint32_t> first(count.size(), 0);
    uint32_t total = 0;
    for (int y = 0; y < tiles_y; ++y)
        for (int x = 0; x < tiles_x; ++x) {
            const size_t t = size_t(y) * size_t(tiles_x) + size_t(x);
            if (count[t] == 0) continue;
            first[t] = total;
            grid.tiles.push_back({uint32_t(x), uint32_t(y), total, count[t]});
            total += count[t];
        }
    grid.indices.resize(total);
    for (const glm::uvec2& p : pairs) grid.indices[first[p.x]++] = p.y;
}

}  // namespace effects
