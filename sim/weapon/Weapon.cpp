#include "sim/weapon/Weapon.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "sim/core/DetMath.h"
#include "sim/player/Player.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/world/World.h"

namespace sim {

namespace {

// What the head runs into at xz: the higher of the ground and the sea there.
struct Surface {
    float height_m;
    bool water;
};

Surface surface_at(const World& world, glm::vec3 p) {
    const glm::vec2 xz(p.x, p.z);
    const float ground = world.terrain().ground_height(xz);
    const float sea = world.sea().height_at(xz);
    return sea >= ground ? Surface{sea, true} : Surface{ground, false};
}

}  // namespace

Weapon::Weapon(uint64_t seed, WeaponParams params) : p_(params), rng_(seed, 0x5eed0fu) {}

void Weapon::fire(glm::vec3 origin, glm::vec3 direction) {
    if (shots_.size() == kMaxShots) shots_.erase(shots_.begin());
    Shot s;
    s.origin = origin;
    s.direction = glm::normalize(direction);
    s.phase = rng_.range(0.0f, 6.2831853f);
    shape(s, kTickSeconds);
    shots_.push_back(s);
}

void Weapon::shape(Shot& s, float dt) const {
    const float t = float(s.age_ticks) * dt;
    const float grown = std::clamp(t / p_.growth_s, 0.0f, 1.0f);
    const float length = p_.max_length_m * grown * grown * (3.0f - 2.0f * grown);  // smoothstep growth
    float fade = std::clamp((p_.life_s - t) / p_.fade_s, 0.0f, 1.0f);
    float head_d = p_.speed_mps * t;
    if (s.hit()) {
        // Stopped at the impact: the tail catches up and the light dies away.
        head_d = s.hit_distance_m;
        fade = std::min(fade, std::clamp(1.0f - float(s.age_ticks - s.hit_age_ticks) * dt / p_.fade_s, 0.0f, 1.0f));
    }
    const float tail_d = std::clamp(p_.speed_mps * t - length, 0.0f, head_d);
    const glm::vec3 head = s.origin + s.direction * head_d;
    const glm::vec3 tail = s.origin + s.direction * tail_d;
    // Sway sideways and up, perpendicular to the flight direction, as much as the beam is long.
    const float reach = std::min(1.0f, (head_d - tail_d) / p_.max_length_m);
    glm::vec3 side = glm::normalize(glm::cross(s.direction, glm::vec3(0, 1, 0)) + glm::vec3(1e-6f, 0, 0));
    glm::vec3 up = glm::cross(side, s.direction);
    glm::vec3 prev = tail;
    for (int i = 0; i < Shot::kSegments; ++i) {
        float f = float(i + 1) / Shot::kSegments;
        glm::vec3 along = tail + (head - tail) * f;
        float w = p_.sway_m * reach * det::sin(s.phase + 7.0f * t + 2.1f * float(i)) *
                  (i + 1 < Shot::kSegments ? 1.0f : 0.0f);
        glm::vec3 end = along + side * w + up * (0.5f * w);
        EnergySegment& seg = s.segments[size_t(i)];
        glm::vec3 d = end - prev;
        float len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        seg.start = prev;
        seg.direction = len > 1e-5f ? d / len : s.direction;
        seg.length_m = len;
        seg.sphere_strength = p_.strength * fade;
        seg.beam_strength = p_.strength * fade;
        seg.radius_m = p_.radius_m;
        prev = end;
    }
}

void Weapon::advance(Shot& s, const World& world, float dt, std::vector<WaterEntry>& water_entries,
                     std::vector<ShotReport>& impacts) const {
    const float before_d = p_.speed_mps * float(s.age_ticks) * dt;
    ++s.age_ticks;
    if (!s.hit()) {
        const float after_d = p_.speed_mps * float(s.age_ticks) * dt;
        const glm::vec3 a = s.origin + s.direction * before_d, b = s.origin + s.direction * after_d;
        const Surface sa = surface_at(world, a), sb = surface_at(world, b);
        const float above_a = a.y - sa.height_m, above_b = b.y - sb.height_m;
        // Where the head crossed the ground or the sea, linearly between the two ticks,
        // unless it ran into a solid (a wall, a crate) first.
        std::optional<float> f;
        if (above_b < 0.0f) f = above_a > 0.0f ? std::clamp(above_a / (above_a - above_b), 0.0f, 1.0f) : 0.0f;
        const std::optional<float> solid = world.terrain().first_solid_hit(a, b);
        const bool into_solid = solid && (!f || *solid < *f);
        if (into_solid) f = solid;
        if (f) {
            s.hit_age_ticks = s.age_ticks;
            s.hit_distance_m = before_d + *f * (after_d - before_d);
            const glm::vec3 at = s.origin + s.direction * s.hit_distance_m;
            const bool water = !into_solid && surface_at(world, at).water;
            if (water)
                water_entries.push_back(
                    WaterEntry{at, s.direction * p_.speed_mps, p_.impact_radius_m, p_.impact_mass_kg, false});
            impacts.push_back({at, into_solid ? ImpactSurface::Solid : water ? ImpactSurface::Water : ImpactSurface::Ground});
        }
    }
    shape(s, dt);
}

void Weapon::connect(const SubsystemLinks& links) {
    player_ = &links.need<Player>();
    car_ = &links.need<Car>();
    boat_ = &links.need<Boat>();
}

void Weapon::step(StepContext& ctx) {
    const Player& player = *player_;
    if (player.fires()) {
        const Pose& pose = player.vehicle() == Vehicle::Car ? car_->pose() : boat_->pose();
        const glm::vec3 fwd = pose.forward_flat();
        const glm::vec3 aim = fwd * det::cos(p_.dip_rad) - glm::vec3(0.0f, det::sin(p_.dip_rad), 0.0f);
        const glm::vec3 muzzle = pose.position + glm::vec3(0.0f, p_.muzzle_height_m, 0.0f) + fwd * p_.muzzle_ahead_m;
        fire(muzzle, aim);
        ctx.world.report().shots_fired.push_back({muzzle, ImpactSurface::Ground});
    }
    // In shot order: the water sees the impacts in the same order every run.
    for (Shot& s : shots_)
        advance(s, ctx.world, ctx.dt, ctx.world.events().water_entries, ctx.world.report().shot_impacts);
    const uint32_t life_ticks = uint32_t(p_.life_s / ctx.dt + 0.5f);
    const uint32_t fade_ticks = uint32_t(p_.fade_s / ctx.dt + 0.5f);
    std::erase_if(shots_, [&](const Shot& s) {
        return s.age_ticks >= life_ticks || (s.hit() && s.age_ticks - s.hit_age_ticks >= fade_ticks);
    });
}


}  // namespace sim
