#include "sim/world/Terrain.h"

#include <algorithm>
#include <cmath>

#include "sim/core/DetMath.h"

namespace sim {

namespace {
// Width of the quay edge where land drops to the sea bed.
constexpr float kQuayWidth_m = 1.0f;
}  // namespace

Terrain::Terrain(const LevelDesc& level) : level_(level) {}

float Terrain::ground_height(glm::vec2 xz) const {
    float hills = 0.0f;
    for (const Hill& h : level_.hills) {
        glm::vec2 d = xz - h.centre_xz;
        hills += h.height_m * det::exp(-(d.x * d.x + d.y * d.y) / (2.0f * h.radius_m * h.radius_m));
    }
    float land = level_.land_height_m + hills;
    float s = (xz.y - level_.shore_z_m) / kQuayWidth_m;  // 0 at the quay, 1 a quay width out
    if (s <= 0.0f) return land;
    if (s >= 1.0f) return level_.seabed_m;
    return land + (level_.seabed_m - land) * s;
}

float Terrain::support_height(glm::vec2 xz, float from_y, float step_m) const {
    float best = ground_height(xz);
    for (const Aabb& d : level_.decks)
        if (d.contains_xz(xz) && d.max.y <= from_y + step_m) best = std::max(best, d.max.y);
    return best;
}

bool Terrain::on_road(glm::vec2 xz) const {
    return std::any_of(level_.roads.begin(), level_.roads.end(), [&](const Rect& r) { return r.contains(xz); });
}

bool Terrain::inside_world(glm::vec2 xz) const {
    float h = level_.half_extent_m;
    return xz.x > -h && xz.x < h && xz.y > -h && xz.y < h;
}

std::optional<float> Terrain::first_solid_hit(glm::vec3 a, glm::vec3 b) const {
    const glm::vec3 ab = b - a;
    std::optional<float> first;
    for (const Aabb& box : level_.solids) {
        // The slabs' common interval of a + t (b - a), t in [0, 1].
        float t0 = 0.0f, t1 = 1.0f;
        for (int k = 0; k < 3 && t0 <= t1; ++k) {
            if (ab[k] == 0.0f) {
                if (a[k] < box.min[k] || a[k] > box.max[k]) t1 = -1.0f;
                continue;
            }
            float u0 = (box.min[k] - a[k]) / ab[k], u1 = (box.max[k] - a[k]) / ab[k];
            if (u0 > u1) std::swap(u0, u1);
            t0 = std::max(t0, u0);
            t1 = std::min(t1, u1);
        }
        if (t0 <= t1 && (!first || t0 < *first)) first = t0;
    }
    return first;
}

std::optional<glm::vec2> Terrain::resolve_solids(glm::vec2& xz, float radius, float y_min, float y_max) const {
    glm::vec2 total(0.0f);
    bool touched = false;
    for (const Aabb& b : level_.solids) {
        if (y_max <= b.min.y || y_min >= b.max.y) continue;
        glm::vec2 closest(std::clamp(xz.x, b.min.x, b.max.x), std::clamp(xz.y, b.min.z, b.max.z));
        glm::vec2 d = xz - closest;
        float dist2 = d.x * d.x + d.y * d.y;
        if (dist2 >= radius * radius) continue;
        glm::vec2 push;
        if (dist2 > 1e-8f) {
            float dist = std::sqrt(dist2);
            push = d * ((radius - dist) / dist);
        } else {
            // Centre inside the box: leave by the nearest face.
            float left = xz.x - b.min.x, right = b.max.x - xz.x;
            float back = xz.y - b.min.z, front = b.max.z - xz.y;
            float m = std::min({left, right, back, front});
            if (m == left) push = {-(left + radius), 0.0f};
            else if (m == right) push = {right + radius, 0.0f};
            else if (m == back) push = {0.0f, -(back + radius)};
            else push = {0.0f, front + radius};
        }
        xz += push;
        total += push;
        touched = true;
    }
    if (!touched) return std::nullopt;
    return total;
}

}  // namespace sim
