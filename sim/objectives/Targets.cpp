#include "sim/objectives/Targets.h"

#include <glm/geometric.hpp>

#include "sim/objects/ThrownObjects.h"
#include "sim/weapon/Weapon.h"

namespace sim {

namespace {

// Squared distance from p to the segment start + [0, length] * direction (unit).
float distance2_to_segment(glm::vec3 p, const EnergySegment& s) {
    float along = glm::dot(p - s.start, s.direction);
    along = along < 0.0f ? 0.0f : (along > s.length_m ? s.length_m : along);
    const glm::vec3 d = p - (s.start + s.direction * along);
    return glm::dot(d, d);
}

// How close a segment's axis must come: the target's radius and the beam's bright core.
constexpr float kShotReach_m = 0.5f;

}  // namespace

Targets::Targets(const std::vector<TargetDesc>& targets) {
    for (const TargetDesc& t : targets) states_.push_back({t});
}

void Targets::hit_by(const std::vector<ThrownObject>& objects, const std::vector<Shot>& shots, uint64_t ticks) {
    for (TargetState& t : states_) {
        if (t.hit()) continue;
        for (const ThrownObject& o : objects) {
            const glm::vec3 d = o.position - t.desc.position;
            const float reach = t.desc.radius_m + o.radius_m;
            if (glm::dot(d, d) <= reach * reach) {
                t.hit_by = HitBy::Object;
                break;
            }
        }
        if (t.hit()) {
            t.hit_at_ticks = ticks;
            continue;
        }
        for (const Shot& s : shots) {
            const float reach = t.desc.radius_m + kShotReach_m;
            for (const EnergySegment& seg : s.segments)
                if (seg.beam_strength > 0.0f && distance2_to_segment(t.desc.position, seg) <= reach * reach)
                    t.hit_by = HitBy::Shot;
            if (t.hit()) break;
        }
        if (t.hit()) t.hit_at_ticks = ticks;
    }
}


size_t Targets::hit_count() const {
    size_t n = 0;
    for (const TargetState& t : states_) n += t.hit() ? 1 : 0;
    return n;
}

}  // namespace sim
