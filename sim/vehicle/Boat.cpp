#include "sim/vehicle/Boat.h"

#include <algorithm>
#include <cmath>

#include "sim/core/DetMath.h"
#include "sim/vehicle/Contact.h"
#include "sim/world/Terrain.h"
#include "sim/world/World.h"

namespace sim {

namespace {
constexpr float kGravity = 9.81f;
constexpr float kWaterDensity = 1000.0f;
constexpr int kSubsteps = 4;
constexpr float kTopSpeedForPlaning_mps = 12.0f;
constexpr ContactMaterial kFender{0.3f, 0.2f};  // hull against stone and timber
constexpr float kResetRingStep_m = 2.0f;
constexpr int kResetRings = 60;
}  // namespace

Boat::Boat(const Spawn& spawn, BoatParams params) : p_(params) {
    pose_.position = spawn.position;
    pose_.heading_rad = spawn.heading_rad;
}

Boat::Boat(const Pose& start, BoatParams params) : p_(params), pose_(start) {}

glm::vec2 Boat::hull_point(int i) const {
    float x = (i & 1) ? -0.37f * p_.length_m : 0.37f * p_.length_m;
    float z = (i & 2) ? 0.38f * p_.beam_m : -0.38f * p_.beam_m;
    return {x, z};
}

glm::vec3 Boat::velocity() const { return u_ * pose_.forward_flat() - v_ * pose_.right_flat(); }

void Boat::connect(const SubsystemLinks& links) { player_ = &links.need<Player>(); }

void Boat::step(StepContext& ctx) {
    const Player& player = *player_;
    if (player.resets() && player.vehicle() == Vehicle::Boat) reset(ctx.world.terrain());
    DriveInput in = player.drive_input(Vehicle::Boat);
    float h = ctx.dt / kSubsteps;
    touch_impulse_ns_ = 0.0f;
    for (int i = 0; i < kSubsteps; ++i) substep(in, ctx.world, h);
    if (touch_impulse_ns_ > 0.0f)
        ctx.world.report().contacts.push_back(
            {ContactBody::Boat, pose_.position + glm::vec3(touch_offset_.x, 0.0f, touch_offset_.y), touch_impulse_ns_});
}

void Boat::substep(const DriveInput& in, const World& world, float h) {
    const Terrain& terrain = world.terrain();
    const SeaSurface& sea = world.sea();
    const float m = p_.mass_kg;

    // In the plane: thrust, quadratic hull drag, rudder turning that needs way on.
    float thrust = in.parked ? 0.0f : in.throttle * p_.thrust_n - in.brake * p_.reverse_thrust_n;
    float du = (thrust - p_.drag_long * u_ * std::fabs(u_)) / m + v_ * r_;
    float dv = -p_.drag_lat * v_ * std::fabs(v_) / m - 0.3f * u_ * r_ - 0.5f * v_;
    float dr = p_.rudder_gain * u_ * in.steer - p_.yaw_damping * r_;
    u_ += du * h;
    v_ += dv * h;
    r_ += dr * h;
    if (in.parked) u_ *= 1.0f - 0.5f * h;  // moored: lines take up the way

    // Out of the plane: linearised buoyancy around the waterline at each hull point.
    const float k_point = kWaterDensity * kGravity * p_.waterplane_area_m2 / kHullPoints;
    float sp = det::sin(pose_.pitch_rad), sr = det::sin(pose_.roll_rad);
    glm::vec3 fwd = pose_.forward_flat(), rt = pose_.right_flat();
    float lift = 0.0f, pitch_torque = 0.0f, roll_torque = 0.0f;
    for (int i = 0; i < kHullPoints; ++i) {
        glm::vec2 hp = hull_point(i);
        glm::vec3 w = pose_.position + fwd * hp.x + rt * hp.y;
        float y = pose_.position.y + hp.x * sp - hp.y * sr;
        float f = std::max(0.0f, m * kGravity / kHullPoints + k_point * (sea.height_at({w.x, w.z}) - y));
        lift += f;
        pitch_torque += f * hp.x;
        roll_torque -= f * hp.y;
    }
    const float pitch_inertia = m * p_.length_m * p_.length_m / 12.0f;
    const float roll_inertia = m * (p_.beam_m * p_.beam_m + 1.5f * 1.5f) / 12.0f;
    const float k_heave = k_point * kHullPoints;
    const float c_heave = 2.0f * p_.heave_damping_ratio * std::sqrt(k_heave * m);
    float plane = p_.planing_pitch_rad * std::clamp(u_ / kTopSpeedForPlaning_mps, 0.0f, 1.0f);
    float k_pitch = k_heave * 0.37f * 0.37f * p_.length_m * p_.length_m;
    float k_roll = k_heave * 0.38f * 0.38f * p_.beam_m * p_.beam_m;
    heave_rate_ += ((lift - m * kGravity) - c_heave * heave_rate_) / m * h;
    pitch_rate_ += (pitch_torque + k_pitch * plane -
                    2.0f * p_.heave_damping_ratio * std::sqrt(k_pitch * pitch_inertia) * pitch_rate_) /
                   pitch_inertia * h;
    roll_rate_ += (roll_torque - 2.0f * p_.heave_damping_ratio * std::sqrt(k_roll * roll_inertia) * roll_rate_) /
                  roll_inertia * h;
    // Turning heels the boat outwards a little.
    roll_rate_ += -0.02f * u_ * r_ * h;

    pose_.position.y += heave_rate_ * h;
    pose_.pitch_rad += pitch_rate_ * h;
    pose_.roll_rad += roll_rate_ * h;
    pose_.heading_rad += r_ * h;
    glm::vec3 vel = velocity();
    pose_.position.x += vel.x * h;
    pose_.position.z += vel.z * h;

    for (int pass = 0; pass < 2; ++pass) {
        touch_solids(terrain);
        touch_shore(terrain);
    }
}

void Boat::touch_solids(const Terrain& terrain) {
    // Pilings and the pier: three circles along the hull pushed out of them.
    const glm::vec3 fwd = pose_.forward_flat();
    const float hull_radius = 0.5f * p_.beam_m;
    for (float along : {0.3f * p_.length_m, 0.0f, -0.3f * p_.length_m}) {
        glm::vec2 c(pose_.position.x + fwd.x * along, pose_.position.z + fwd.z * along);
        auto push = terrain.resolve_solids(c, hull_radius, pose_.position.y - 0.5f, pose_.position.y + 1.8f);
        if (!push) continue;
        float depth = std::sqrt(push->x * push->x + push->y * push->y);
        if (depth < 1e-6f) continue;
        glm::vec2 n = *push / depth;
        pose_.position.x += push->x;
        pose_.position.z += push->y;
        touch(glm::vec2(fwd.x, fwd.z) * along - n * hull_radius, n);
    }
}

bool Boat::navigable(const Terrain& terrain, glm::vec2 xz) const {
    return terrain.inside_world(xz) && terrain.ground_height(xz) <= terrain.level().sea_level_m - p_.min_depth_m;
}

void Boat::touch_shore(const Terrain& terrain) {
    // Shallows and the world's edge: bow and stern are put back into deep enough water
    // and the boat slides along, as off a fender.
    const glm::vec3 fwd = pose_.forward_flat();
    auto deep = [&](glm::vec2 xz) { return navigable(terrain, xz); };
    const glm::vec2 bow(fwd.x * 0.5f * p_.length_m, fwd.z * 0.5f * p_.length_m);
    push_back_across_edges(pose_.position, {bow, -bow}, deep,
                           [&](glm::vec2 offset, glm::vec2 normal) { touch(offset, normal); });
}

void Boat::touch(glm::vec2 offset, glm::vec2 normal) {
    const glm::vec3 fwd = pose_.forward_flat(), left = -pose_.right_flat();
    glm::vec3 w = velocity();
    const float yaw_inertia = p_.mass_kg * (p_.length_m * p_.length_m + p_.beam_m * p_.beam_m) / 12.0f;
    PlanarBody body{{w.x, w.z}, r_, p_.mass_kg, yaw_inertia};
    const glm::vec2 before = body.velocity;
    sim::touch(body, offset, normal, kFender);
    // The impulse along the normal, from the change of momentum it made.
    const float impulse = p_.mass_kg * ((body.velocity.x - before.x) * normal.x + (body.velocity.y - before.y) * normal.y);
    if (impulse > touch_impulse_ns_) {
        touch_impulse_ns_ = impulse;
        touch_offset_ = offset;
    }
    u_ = body.velocity.x * fwd.x + body.velocity.y * fwd.z;
    v_ = body.velocity.x * left.x + body.velocity.y * left.z;
    r_ = body.yaw_rate;
}

bool Boat::fits(const Terrain& terrain, glm::vec2 xz, float heading_rad) const {
    Pose at;
    at.heading_rad = heading_rad;
    glm::vec3 fwd = at.forward_flat(), right = at.right_flat();
    float sea = terrain.level().sea_level_m;
    for (float along : {-0.6f, 0.0f, 0.6f})
        for (float side : {-0.6f, 0.0f, 0.6f}) {
            glm::vec2 c = xz + glm::vec2(fwd.x, fwd.z) * (along * p_.length_m) + glm::vec2(right.x, right.z) * (side * p_.beam_m);
            if (!navigable(terrain, c)) return false;
        }
    for (float along : {0.3f * p_.length_m, 0.0f, -0.3f * p_.length_m}) {
        glm::vec2 c = xz + glm::vec2(fwd.x, fwd.z) * along;
        if (terrain.resolve_solids(c, 0.5f * p_.beam_m + 0.5f, sea - 0.5f, sea + 1.8f)) return false;
    }
    return true;
}

void Boat::reset(const Terrain& terrain) {
    // The nearest open water the hull fits in with room to spare, on rings of growing
    // radius around the boat, keeping its heading; failing that, the spawn point.
    const LevelDesc& level = terrain.level();
    glm::vec2 here(pose_.position.x, pose_.position.z);
    glm::vec2 spot(level.boat_spawn.position.x, level.boat_spawn.position.z);
    float heading = pose_.heading_rad;
    bool found = fits(terrain, here, heading);
    if (found) spot = here;
    for (int ring = 1; ring <= kResetRings && !found; ++ring) {
        const int directions = 8 * ring;
        for (int k = 0; k < directions && !found; ++k) {
            float s, c;
            det::sincos(6.2831853f * float(k) / float(directions), s, c);
            glm::vec2 at = here + glm::vec2(c, s) * (kResetRingStep_m * float(ring));
            if (fits(terrain, at, heading)) {
                spot = at;
                found = true;
            }
        }
    }
    if (!found) heading = level.boat_spawn.heading_rad;
    pose_ = Pose{};
    pose_.position = {spot.x, level.sea_level_m, spot.y};
    pose_.heading_rad = heading;
    u_ = v_ = r_ = heave_rate_ = pitch_rate_ = roll_rate_ = 0.0f;
}


}  // namespace sim
