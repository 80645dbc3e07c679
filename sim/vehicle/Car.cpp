#include "sim/vehicle/Car.h"

#include <algorithm>
#include <cmath>

#include "sim/core/DetMath.h"
#include "sim/core/Hash.h"
#include "sim/world/Terrain.h"
#include "sim/world/World.h"

namespace sim {

namespace {
constexpr float kGravity = 9.81f;
constexpr int kSubsteps = 4;
constexpr float kTrack_m = 1.6f;
constexpr float kMaxStep_m = 0.6f;

float move_towards(float x, float target, float max_delta) {
    return x + std::clamp(target - x, -max_delta, max_delta);
}
}  // namespace

Car::Car(const Spawn& spawn, CarParams params) : p_(params) {
    pose_.position = spawn.position;
    pose_.heading_rad = spawn.heading_rad;
}

glm::vec3 Car::velocity() const {
    glm::vec3 left = -pose_.right_flat();
    return u_ * pose_.forward_flat() + v_ * left;
}

void Car::step(StepContext& ctx) {
    const Terrain& terrain = ctx.world.terrain();
    DriveInput in = ctx.world.get<Player>().drive_input(Vehicle::Car);
    float u0 = u_, v0 = v_;
    float h = ctx.dt / kSubsteps;
    // Reverse engages only from (nearly) standing still, decided once per tick, so
    // braking to a stop never carries on into reverse within the same tick.
    bool reverse = in.brake > 0.0f && in.throttle == 0.0f && !in.parked && u_ <= 0.05f;
    for (int i = 0; i < kSubsteps; ++i) substep(in, reverse, terrain, h);
    follow_ground(terrain);
    accel_ = {(u_ - u0) / ctx.dt, (v_ - v0) / ctx.dt + u_ * r_};
    wheel_spin_ = std::fmod(wheel_spin_ + u_ * ctx.dt / 0.33f, 6.2831853f);
}

void Car::substep(const DriveInput& in, bool reverse, const Terrain& terrain, float h) {
    const float a = p_.cg_to_front_m, b = p_.cg_to_rear_m, wheelbase = a + b;
    const float fz_front = p_.mass_kg * kGravity * b / wheelbase;
    const float fz_rear = p_.mass_kg * kGravity * a / wheelbase;
    glm::vec2 xz(pose_.position.x, pose_.position.z);
    const float mu = terrain.on_road(xz) ? p_.grip_road : p_.grip_off_road;

    // Steering slows down at speed, like a driver would.
    float steer_target = in.steer * p_.max_steer_rad / (1.0f + std::fabs(u_) / 20.0f);
    steer_ = move_towards(steer_, steer_target, p_.steer_rate_radps * h);

    // Longitudinal: rear-wheel drive limited by rear grip; brakes on all wheels.
    float drive = 0.0f;
    float brake = 0.0f;
    if (in.parked) {
        brake = p_.brake_force_n;
    } else if (reverse) {
        drive = u_ > -p_.reverse_speed_mps ? -0.5f * p_.engine_force_n * in.brake : 0.0f;
    } else if (in.brake > 0.0f) {
        brake = p_.brake_force_n * in.brake;
    } else if (in.throttle > 0.0f) {
        drive = in.throttle * std::min(p_.engine_force_n, p_.engine_power_w / std::max(std::fabs(u_), 1.0f));
    } else {
        brake = p_.engine_braking_n;
    }
    drive = std::clamp(drive, -mu * fz_rear, mu * fz_rear);
    brake = std::min(brake, mu * p_.mass_kg * kGravity);
    float sign_u = u_ > 0.0f ? 1.0f : (u_ < 0.0f ? -1.0f : 0.0f);
    float fx = drive - sign_u * p_.rolling_resist_n - p_.drag_coeff * u_ * std::fabs(u_);

    // Lateral: slip angles and saturating tyre forces.
    // Slip angles against the direction of travel: in reverse the sliding speed is
    // still opposed and the steered wheels turn the car the other way.
    float speed = std::max(std::fabs(u_), 1.0f);
    float travel = u_ < 0.0f ? -1.0f : 1.0f;
    float alpha_f = det::atan((v_ + a * r_) / speed) - travel * steer_;
    float alpha_r = det::atan((v_ - b * r_) / speed);
    float cap_f = mu * fz_front, cap_r = mu * fz_rear;
    float fy_f = -cap_f * det::tanh(p_.cornering_stiffness_npr * alpha_f / cap_f);
    float fy_r = -cap_r * det::tanh(p_.cornering_stiffness_npr * alpha_r / cap_r);

    float cs = det::cos(steer_), sn = det::sin(steer_);
    float du = (fx - fy_f * sn) / p_.mass_kg + v_ * r_;
    float dv = (fy_f * cs + fy_r) / p_.mass_kg - u_ * r_;
    float dr = (a * fy_f * cs - b * fy_r) / p_.yaw_inertia_kgm2;
    u_ += du * h;
    v_ += dv * h;
    r_ += dr * h;
    // Brakes stop the car; they never push it backwards.
    float brake_dv = brake / p_.mass_kg * h;
    u_ = std::fabs(u_) <= brake_dv ? 0.0f : u_ - brake_dv * (u_ > 0.0f ? 1.0f : -1.0f);

    // Below walking pace tyre slip is meaningless: blend into rolling without slip,
    // where the rear axle has no sideways speed (v = b r) and r = u tan(steer) / L.
    float k = std::clamp((std::fabs(u_) - 1.0f) / 2.0f, 0.0f, 1.0f);
    float r_kinematic = u_ * det::tan(steer_) / wheelbase;
    float v_kinematic = b * r_kinematic;
    r_ = r_kinematic + (r_ - r_kinematic) * k;
    v_ = v_kinematic + (v_ - v_kinematic) * k;

    Pose before = pose_;
    pose_.heading_rad += r_ * h;
    glm::vec3 vel = velocity();
    pose_.position.x += vel.x * h;
    pose_.position.z += vel.z * h;

    // Solids: push both axle circles out and take away the speed into the wall.
    glm::vec3 fwd = pose_.forward_flat();
    float y0 = pose_.position.y + 0.25f, y1 = pose_.position.y + p_.height_m;
    for (float along : {a, -b}) {
        glm::vec2 c(pose_.position.x + fwd.x * along, pose_.position.z + fwd.z * along);
        if (auto push = terrain.resolve_solids(c, p_.radius_m, y0, y1)) {
            pose_.position.x += push->x;
            pose_.position.z += push->y;
            glm::vec2 n = *push / std::max(std::sqrt(push->x * push->x + push->y * push->y), 1e-6f);
            glm::vec3 w = velocity();
            float into = w.x * n.x + w.z * n.y;
            if (into < 0.0f) {
                w.x -= 1.2f * into * n.x;
                w.z -= 1.2f * into * n.y;
                glm::vec3 left = -pose_.right_flat();
                u_ = w.x * fwd.x + w.z * fwd.z;
                v_ = w.x * left.x + w.z * left.z;
                r_ *= 0.5f;
            }
        }
    }

    // Water's edge, the end of the world, or a wall too high to climb: stop there.
    // Every corner of the body (with a little margin) must have ground under it.
    glm::vec3 right = pose_.right_flat();
    bool blocked = false;
    for (float along : {a + 0.8f, -b - 0.8f})
        for (float side : {-0.5f * kTrack_m - 0.1f, 0.5f * kTrack_m + 0.1f}) {
            glm::vec2 c(pose_.position.x + fwd.x * along + right.x * side,
                        pose_.position.z + fwd.z * along + right.z * side);
            float ground = terrain.support_height(c, before.position.y, kMaxStep_m);
            blocked = blocked || !terrain.inside_world(c) || ground < terrain.level().sea_level_m + 0.1f ||
                      ground > before.position.y + kMaxStep_m;
        }
    if (blocked) {
        pose_ = before;
        u_ *= -0.2f;
        v_ = 0.0f;
        r_ = 0.0f;
    }
}

void Car::follow_ground(const Terrain& terrain) {
    glm::vec3 f = pose_.forward_flat(), rt = pose_.right_flat(), p = pose_.position;
    // A wheel over an edge rests at the body's height rather than dropping with it.
    float centre = terrain.support_height({p.x, p.z}, p.y, kMaxStep_m);
    auto at = [&](glm::vec3 off) {
        return std::max(terrain.support_height({p.x + off.x, p.z + off.z}, p.y, kMaxStep_m), centre - 0.3f);
    };
    float front = at(f * p_.cg_to_front_m), rear = at(-f * p_.cg_to_rear_m);
    float left = at(-rt * (kTrack_m * 0.5f)), right = at(rt * (kTrack_m * 0.5f));
    pose_.position.y = 0.5f * (0.5f * (front + rear) + 0.5f * (left + right));
    pose_.pitch_rad = det::atan2(front - rear, p_.cg_to_front_m + p_.cg_to_rear_m);
    pose_.roll_rad = det::atan2(left - right, kTrack_m);
}

uint64_t Car::hash() const {
    Hasher hs;
    hs.vec(pose_.position);
    hs.f32(pose_.heading_rad);
    hs.f32(pose_.pitch_rad);
    hs.f32(pose_.roll_rad);
    hs.f32(u_);
    hs.f32(v_);
    hs.f32(r_);
    hs.f32(steer_);
    hs.f32(wheel_spin_);
    return hs.value();
}

}  // namespace sim
