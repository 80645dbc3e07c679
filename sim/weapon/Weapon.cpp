#include "sim/weapon/Weapon.h"

#include <algorithm>
#include <cmath>

#include "sim/core/Hash.h"
#include "sim/player/Player.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/world/World.h"

namespace sim {

Weapon::Weapon(uint64_t seed, WeaponParams params) : p_(params), rng_(seed, 0x5eed0fu) {}

void Weapon::fire(glm::vec3 origin, glm::vec3 direction) {
    if (shots_.size() == kMaxShots) shots_.erase(shots_.begin());
    Shot s;
    s.origin = origin;
    s.direction = glm::normalize(direction);
    s.phase = rng_.range(0.0f, 6.2831853f);
    shots_.push_back(s);
}

void Weapon::shape(Shot& s, float dt) const {
    float t = float(s.age_ticks) * dt;
    float grown = std::clamp(t / p_.growth_s, 0.0f, 1.0f);
    float length = p_.max_length_m * grown * grown * (3.0f - 2.0f * grown);  // smoothstep growth
    float fade = std::clamp((p_.life_s - t) / p_.fade_s, 0.0f, 1.0f);
    glm::vec3 head = s.origin + s.direction * (p_.speed_mps * t);
    glm::vec3 tail = head - s.direction * length;
    // Sway sideways and up, perpendicular to the flight direction.
    glm::vec3 side = glm::normalize(glm::cross(s.direction, glm::vec3(0, 1, 0)) + glm::vec3(1e-6f, 0, 0));
    glm::vec3 up = glm::cross(side, s.direction);
    glm::vec3 prev = tail;
    for (int i = 0; i < Shot::kSegments; ++i) {
        float f = float(i + 1) / Shot::kSegments;
        glm::vec3 along = tail + (head - tail) * f;
        float w = p_.sway_m * grown * std::sin(s.phase + 7.0f * t + 2.1f * float(i)) * (i + 1 < Shot::kSegments ? 1.0f : 0.0f);
        glm::vec3 end = along + side * w + up * (0.5f * w);
        EnergySegment& seg = s.segments[size_t(i)];
        glm::vec3 d = end - prev;
        float len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        seg.start = prev;
        seg.direction = len > 1e-5f ? d / len : s.direction;
        seg.length_m = len;
        seg.sphere_strength = p_.strength * fade;
        seg.beam_strength = p_.strength * fade;
        prev = end;
    }
}

void Weapon::step(StepContext& ctx) {
    const Player& player = ctx.world.get<Player>();
    if (player.fires()) {
        const Pose& pose = player.vehicle() == Vehicle::Car ? ctx.world.get<Car>().pose() : ctx.world.get<Boat>().pose();
        glm::vec3 fwd = pose.forward_flat();
        fire(pose.position + glm::vec3(0.0f, 1.4f, 0.0f) + fwd * 3.0f, fwd);
    }
    for (Shot& s : shots_) {
        ++s.age_ticks;
        shape(s, ctx.dt);
    }
    const uint32_t life_ticks = uint32_t(p_.life_s / ctx.dt + 0.5f);
    std::erase_if(shots_, [&](const Shot& s) { return s.age_ticks >= life_ticks; });
}

uint64_t Weapon::hash() const {
    Hasher h;
    h.u64(rng_.state());
    h.u32(uint32_t(shots_.size()));
    for (const Shot& s : shots_) {
        h.vec(s.origin);
        h.vec(s.direction);
        h.f32(s.phase);
        h.u32(s.age_ticks);
        for (const EnergySegment& seg : s.segments) {
            h.vec(seg.start);
            h.vec(seg.direction);
            h.f32(seg.length_m);
            h.f32(seg.sphere_strength);
            h.f32(seg.beam_strength);
        }
    }
    return h.value();
}

}  // namespace sim
