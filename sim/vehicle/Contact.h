#pragma once
// Vehicles touching what they cannot drive through: solids, the water's edge (or, for
// the boat, the shore), the world's border. A touch takes away the speed into the
// obstacle at the touching point (a little of it bounces back), rubs off some speed
// along it, and keeps the rest: the vehicle slides along instead of sticking.
#include <cmath>
#include <initializer_list>
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/core/DetMath.h"

namespace sim {

// A vehicle in the ground plane (x, z): velocity and yaw rate (positive turns +x
// towards -z, like Pose::heading_rad).
struct PlanarBody {
    glm::vec2 velocity{0.0f};
    float yaw_rate = 0.0f;
    float mass_kg = 1.0f;
    float yaw_inertia_kgm2 = 1.0f;
};

struct ContactMaterial {
    float restitution = 0.2f;  // share of the speed into the obstacle that bounces back
    float friction = 0.3f;     // scraping along it
};

// An impulse at `offset` from the body's centre, along `normal` (unit, pointing away
// from the obstacle), if that point moves into the obstacle; friction along the edge
// is bounded by it.
void touch(PlanarBody& body, glm::vec2 offset, glm::vec2 normal, ContactMaterial material);

struct EdgeContact {
    glm::vec2 normal{0.0f};  // the way back to allowed ground
    float depth_m = 0.0f;    // how far
};

// For a point of a vehicle that has left the ground it may be on: the shortest way
// back, found on rings of growing radius around it (the mean direction of the first
// ring's allowed points faces straight back across a straight edge), its length
// refined by bisection. nullopt if the point is allowed, or if nothing is allowed within
// the search radius: only a vehicle set down there can be that far over, and it is left
// where it is rather than thrown about.
template <class Allowed>
std::optional<EdgeContact> edge_contact(glm::vec2 point, const Allowed& allowed) {
    if (allowed(point)) return std::nullopt;
    constexpr int kDirections = 24;
    constexpr int kRings = 12;
    constexpr float kRingStep_m = 0.1f;
    for (int ring = 1; ring <= kRings; ++ring) {
        const float radius = kRingStep_m * float(ring);
        glm::vec2 sum(0.0f);
        int found = 0;
        for (int k = 0; k < kDirections; ++k) {
            float s, c;
            det::sincos(6.2831853f * float(k) / kDirections, s, c);
            if (allowed(point + glm::vec2(c, s) * radius)) {
                sum += glm::vec2(c, s);
                ++found;
            }
        }
        if (found == 0) continue;
        float len = std::sqrt(sum.x * sum.x + sum.y * sum.y);
        if (len < 1e-4f) continue;  // allowed on opposite sides alike: a thin strip
        glm::vec2 n = sum / len;
        float lo = radius - kRingStep_m, hi = radius;
        if (!allowed(point + n * hi)) return EdgeContact{n, hi};
        for (int i = 0; i < 5; ++i) {
            float mid = 0.5f * (lo + hi);
            (allowed(point + n * mid) ? hi : lo) = mid;
        }
        return EdgeContact{n, hi};
    }
    return std::nullopt;
}

// Each of a vehicle's points at `offsets` from its centre (ground plane) that has left
// the ground it may be on is put back across the edge, moving the vehicle's `position`,
// and touches it: touch(offset, normal). The car's corners and the boat's bow and stern
// alike; a point is tested where the pushes before it have left the vehicle.
template <class Allowed, class Touch>
void push_back_across_edges(glm::vec3& position, std::initializer_list<glm::vec2> offsets, const Allowed& allowed,
                            Touch&& touch) {
    for (glm::vec2 offset : offsets)
        if (auto edge = edge_contact(glm::vec2(position.x, position.z) + offset, allowed)) {
            position.x += edge->normal.x * edge->depth_m;
            position.z += edge->normal.y * edge->depth_m;
            touch(offset, edge->normal);
        }
}

}  // namespace sim
