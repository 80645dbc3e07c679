#include "sim/vehicle/Boat.h"

#include <algorithm>
#include <cmath>

#include "sim/core/DetMath.h"
#include "sim/core/Hash.h"
#include "sim/world/Terrain.h"
#include "sim/world/World.h"

namespace sim {

namespace {
constexpr float kGravity = 9.81f;
constexpr float kWaterDensity = 1000.0f;
constexpr int kSubsteps = 4;
constexpr float kTopSpeedForPlaning_mps = 12.0f;
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

void Boat::step(StepContext& ctx) {
    DriveInput in = ctx.world.get<Player>().drive_input(Vehicle::Boat);
    float h = ctx.dt / kSubsteps;
    for (int i = 0; i < kSubsteps; ++i) substep(in, ctx.world, h);
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

    Pose before = pose_;
    pose_.position.y += heave_rate_ * h;
    pose_.pitch_rad += pitch_rate_ * h;
    pose_.roll_rad += roll_rate_ * h;
    pose_.heading_rad += r_ * h;
    glm::vec3 vel = velocity();
    pose_.position.x += vel.x * h;
    pose_.position.z += vel.z * h;

    // Pilings and the pier: push out, lose the speed into them.
    fwd = pose_.forward_flat();
    float hull_radius = 0.5f * p_.beam_m;
    for (float along : {0.3f * p_.length_m, 0.0f, -0.3f * p_.length_m}) {
        glm::vec2 c(pose_.position.x + fwd.x * along, pose_.position.z + fwd.z * along);
        if (auto push = terrain.resolve_solids(c, hull_radius, pose_.position.y - 0.5f, pose_.position.y + 1.8f)) {
            pose_.position.x += push->x;
            pose_.position.z += push->y;
            u_ *= 0.5f;
            v_ = 0.0f;
        }
    }
    // Shallows and the world's edge: run aground softly.
    for (float along : {0.5f * p_.length_m, -0.5f * p_.length_m}) {
        glm::vec2 c(pose_.position.x + fwd.x * along, pose_.position.z + fwd.z * along);
        bool aground = !terrain.inside_world(c) ||
                       terrain.ground_height(c) > terrain.level().sea_level_m - p_.min_depth_m;
        if (aground) {
            pose_.position.x = before.position.x;
            pose_.position.z = before.position.z;
            pose_.heading_rad = before.heading_rad;
            u_ *= -0.2f;
            v_ = 0.0f;
            r_ = 0.0f;
            break;
        }
    }
}

uint64_t Boat::hash() const {
    Hasher hs;
    hs.vec(pose_.position);
    hs.f32(pose_.heading_rad);
    hs.f32(pose_.pitch_rad);
    hs.f32(pose_.roll_rad);
    for (float f : {u_, v_, r_, heave_rate_, pitch_rate_, roll_rate_}) hs.f32(f);
    return hs.value();
}

}  // namespace sim
