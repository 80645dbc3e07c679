#include "effects/scene/ObjectiveMarkers.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "sim/objectives/Objectives.h"
#include "sim/world/Terrain.h"

namespace effects {

namespace {

constexpr float kPostHeight_m = 5.6f;  // the banner clears the chase camera (3.2 m over the vehicle)
constexpr float kPostHalfWidth_m = 0.14f;
constexpr float kBannerHalfHeight_m = 0.35f;
constexpr float kBannerHalfDepth_m = 0.05f;

const glm::vec4 kPostTint(0.85f, 0.85f, 0.82f, 1.0f);
const glm::vec4 kBannerTint(0.08f, 0.22f, 0.75f, 1.0f);
const glm::vec4 kStartBannerTint(0.9f, 0.9f, 0.9f, 1.0f);  // the start and finish line
const glm::vec4 kNextTint(1.0f, 0.62f, 0.1f, 1.0f);
const glm::vec4 kCrateTint(0.8f, 0.16f, 0.08f, 1.0f);
const glm::vec4 kBuoyTint(0.95f, 0.35f, 0.05f, 1.0f);
const glm::vec4 kHitTint(0.2f, 0.8f, 0.25f, 1.0f);

// A box with half extents `half`, turned `heading_rad` about +y (the level's heading:
// positive turns from +x towards -z), centred at `centre`.
ObjectiveMarker box(glm::vec3 centre, glm::vec3 half, float heading_rad, glm::vec4 tint, ObjectiveMarker::Glow glow) {
    ObjectiveMarker m;
    m.transform = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), centre), heading_rad, glm::vec3(0.0f, 1.0f, 0.0f)), half);
    m.tint = tint;
    m.glow = glow;
    const float reach = std::sqrt(half.x * half.x + half.z * half.z);
    m.lo = centre - glm::vec3(reach, half.y, reach);
    m.hi = centre + glm::vec3(reach, half.y, reach);
    return m;
}

// Posts from `base_y` up to kPostHeight_m above `ground_y` (the sea's posts start below
// its surface, so no wave shows their foot).
void add_gate(const sim::GatePosts& posts, float ground_y, float base_y, bool next, bool start,
              std::vector<ObjectiveMarker>& out) {
    const ObjectiveMarker::Glow glow = next ? ObjectiveMarker::Glow::Next : ObjectiveMarker::Glow::None;
    const float top_y = ground_y + kPostHeight_m;
    for (glm::vec2 p : {posts.left, posts.right})
        out.push_back(box({p.x, 0.5f * (base_y + top_y), p.y}, {kPostHalfWidth_m, 0.5f * (top_y - base_y), kPostHalfWidth_m},
                          0.0f, next ? kNextTint : kPostTint, ObjectiveMarker::Glow::None));
    const glm::vec2 across = posts.right - posts.left;
    const glm::vec2 mid = 0.5f * (posts.left + posts.right);
    const float half_length = 0.5f * std::sqrt(across.x * across.x + across.y * across.y);
    // The banner's long axis is the box's x: turned onto the line between the posts.
    const float heading = std::atan2(-across.y, across.x);
    out.push_back(box({mid.x, top_y - kBannerHalfHeight_m, mid.y},
                      {half_length, kBannerHalfHeight_m, kBannerHalfDepth_m}, heading,
                      next ? kNextTint : (start ? kStartBannerTint : kBannerTint), glow));
}

}  // namespace

std::vector<ObjectiveMarker> objective_markers(const sim::World& world) {
    std::vector<ObjectiveMarker> out;
    const auto* objectives = world.find<sim::Objectives>();
    if (!objectives) return out;
    const sim::LevelDesc& level = world.terrain().level();
    for (const sim::Course& c : objectives->courses()) {
        const bool boat = c.desc().vehicle == sim::CourseVehicle::Boat;
        for (size_t g = 0; g < c.desc().gates.size(); ++g) {
            const sim::GatePosts& posts = c.posts(g);
            // Posts stand on the ground, or in the sea.
            const float ground_y = boat ? level.sea_level_m
                                        : std::min(world.terrain().ground_height(posts.left), world.terrain().ground_height(posts.right));
            add_gate(posts, ground_y, boat ? ground_y - 1.0f : ground_y, g == c.next_gate(), g == 0, out);
        }
    }
    for (const sim::TargetState& t : objectives->targets().states()) {
        const float r = t.desc.radius_m;
        if (t.desc.kind == sim::TargetKind::Buoy) {
            ObjectiveMarker m;
            m.shape = ObjectiveMarker::Shape::Ball;
            m.transform = glm::scale(glm::translate(glm::mat4(1.0f), t.desc.position), glm::vec3(r));
            m.tint = t.hit() ? kHitTint : kBuoyTint;
            m.glow = t.hit() ? ObjectiveMarker::Glow::Hit : ObjectiveMarker::Glow::None;
            m.lo = t.desc.position - r;
            m.hi = t.desc.position + r;
            out.push_back(m);
            continue;
        }
        // A crate stands on end, its centre at the target's; once hit it lies on its side.
        const glm::vec3 half(0.6f * r, r, 0.6f * r);
        if (!t.hit()) {
            out.push_back(box(t.desc.position, half, 0.0f, kCrateTint, ObjectiveMarker::Glow::None));
            continue;
        }
        const float ground = world.terrain().ground_height({t.desc.position.x, t.desc.position.z});
        const glm::vec3 lying(t.desc.position.x + 0.4f * r, ground + half.x, t.desc.position.z);
        ObjectiveMarker m = box(lying, {half.y, half.x, half.z}, 0.0f, kHitTint, ObjectiveMarker::Glow::None);
        out.push_back(m);
    }
    return out;
}

}  // namespace effects
