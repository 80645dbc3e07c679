#include "sim/vehicle/Car.h"

#include <algorithm>
#include <cmath>

#include "sim/core/DetMath.h"
#include "sim/vehicle/Contact.h"
#include "sim/world/Terrain.h"
#include "sim/world/World.h"

namespace sim {

namespace {
constexpr float kGravity = 9.81f;
constexpr int kSubsteps = 4;
constexpr float kTrack_m = 1.6f;
constexpr float kMaxStep_m = 0.6f;
constexpr float kResetStep_m = 2.0f;  // tries along a road for a free spot, either way
constexpr int kResetTries = 40;
constexpr ContactMaterial kScrape{0.2f, 0.3f};  // steel body on stone and iron
constexpr float kScrapeHold_s = 0.1f;  // a contact this recent still counts as scraping
constexpr float kScrapeTurnDecay_s = 0.15f;

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

void Car::connect(const SubsystemLinks& links) { player_ = &links.need<Player>(); }

void Car::step(StepContext& ctx) {
    const Terrain& terrain = ctx.world.terrain();
    const Player& player = *player_;
    if (player.resets() && player.vehicle() == Vehicle::Car) reset(terrain);
    DriveInput in = player.drive_input(Vehicle::Car);
    float u0 = u_, v0 = v_;
    float h = ctx.dt / kSubsteps;
    // Reverse engages only from (nearly) standing still, decided once per tick, so
    // braking to a stop never carries on into reverse within the same tick.
    bool reverse = in.brake > 0.0f && in.throttle == 0.0f && !in.parked && u_ <= 0.05f;
    touch_impulse_ns_ = 0.0f;
    for (int i = 0; i < kSubsteps; ++i) substep(in, reverse, terrain, h);
    follow_ground(terrain);
    if (touch_impulse_ns_ > 0.0f)
        ctx.world.report().contacts.push_back(
            {ContactBody::Car, pose_.position + glm::vec3(touch_offset_.x, 0.0f, touch_offset_.y), touch_impulse_ns_});
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
    // Below walking pace tyre slip is meaningless (the slip angles above are taken against
    // at least 1 m/s): the tyres' side forces fade out, so that a car at rest with the
    // wheel on full lock does not brake itself and can drive or reverse away.
    float k = std::clamp((std::fabs(u_) - 1.0f) / 2.0f, 0.0f, 1.0f);
    float fy_f = -k * cap_f * det::tanh(p_.cornering_stiffness_npr * alpha_f / cap_f);
    float fy_r = -k * cap_r * det::tanh(p_.cornering_stiffness_npr * alpha_r / cap_r);

    float cs = det::cos(steer_), sn = det::sin(steer_);
    float du = (fx - fy_f * sn) / p_.mass_kg + v_ * r_;
    float dv = (fy_f * cs + fy_r) / p_.mass_kg - u_ * r_;
    float dr = (a * fy_f * cs - b * fy_r) / p_.yaw_inertia_kgm2;
    // Pressed against something, the steered front wheels still scrub the nose round
    // the way they point and are driven: how a car nosed into a post or a wall turns off
    // it. They scrub at full lock's slip, whatever the body does: held against a bollard
    // by the quay edge the nose can only turn by sliding along the bollard, and the slip
    // measured from that slide would all but stop it. The way the wheels are driven, not
    // the sign of the speed: the bounce off the obstacle leaves a car pressed forward
    // rolling back at a few mm/s, and following that would flip the scrub every substep.
    if (scraping_s_ > 0.0f) {
        const float driven = drive > 0.0f ? 1.0f : (drive < 0.0f ? -1.0f : travel);
        const float fy_scrub = cap_f * det::tanh(p_.cornering_stiffness_npr * driven * steer_ / cap_f);
        dr += (1.0f - k) * a * fy_scrub * cs / p_.yaw_inertia_kgm2;
    }
    u_ += du * h;
    v_ += dv * h;
    r_ += dr * h;
    // Brakes stop the car; they never push it backwards.
    float brake_dv = brake / p_.mass_kg * h;
    u_ = std::fabs(u_) <= brake_dv ? 0.0f : u_ - brake_dv * (u_ > 0.0f ? 1.0f : -1.0f);

    // Slow, the car rolls without slip instead: blend into it, where the rear axle has no
    // sideways speed (v = b r) and r = u tan(steer) / L. While scraping along something the turn
    // the contact gave the car dies away over a moment instead, so that a car nosed into
    // a wall at an angle pivots along it rather than stalling.
    k = std::clamp((std::fabs(u_) - 1.0f) / 2.0f, 0.0f, 1.0f);
    float r_kinematic = u_ * det::tan(steer_) / wheelbase;
    float r_rolling = r_kinematic + (r_ - r_kinematic) * k;
    r_ = scraping_s_ > 0.0f ? r_ + (r_rolling - r_) * std::min(1.0f, h / kScrapeTurnDecay_s) : r_rolling;
    v_ = b * r_ + (v_ - b * r_) * k;
    scraping_s_ = std::max(0.0f, scraping_s_ - h);

    pose_.heading_rad += r_ * h;
    glm::vec3 vel = velocity();
    pose_.position.x += vel.x * h;
    pose_.position.z += vel.z * h;

    // Twice, because leaving a solid can put a corner over an edge and back.
    for (int pass = 0; pass < 2; ++pass) {
        touch_solids(terrain);
        touch_edges(terrain);
    }
}

void Car::touch_solids(const Terrain& terrain) {
    // Both axle circles: pushed out of walls, posts and crates.
    const glm::vec3 fwd = pose_.forward_flat();
    const float y0 = pose_.position.y + 0.25f, y1 = pose_.position.y + p_.height_m;
    for (float along : {p_.cg_to_front_m, -p_.cg_to_rear_m}) {
        glm::vec2 c(pose_.position.x + fwd.x * along, pose_.position.z + fwd.z * along);
        auto push = terrain.resolve_solids(c, p_.radius_m, y0, y1);
        if (!push) continue;
        float depth = std::sqrt(push->x * push->x + push->y * push->y);
        if (depth < 1e-6f) continue;
        glm::vec2 n = *push / depth;
        pose_.position.x += push->x;
        pose_.position.z += push->y;
        touch(glm::vec2(fwd.x, fwd.z) * along - n * p_.radius_m, n);
    }
}

void Car::touch_edges(const Terrain& terrain) {
    // Every corner of the body (with a little margin) must have ground under it: not the
    // sea, not outside the world, not a rise too high to climb. A corner past such an
    // edge is put back across it and the car slides along.
    const float y = pose_.position.y, sea = terrain.level().sea_level_m;
    auto drivable = [&](glm::vec2 xz) {
        if (!terrain.inside_world(xz)) return false;
        float ground = terrain.support_height(xz, y, kMaxStep_m);
        return ground >= sea + 0.1f && ground <= y + kMaxStep_m;
    };
    const glm::vec3 fwd3 = pose_.forward_flat(), right3 = pose_.right_flat();
    const glm::vec2 fwd(fwd3.x, fwd3.z), right(right3.x, right3.z);
    const float front = p_.cg_to_front_m + 0.8f, rear = -p_.cg_to_rear_m - 0.8f, side = 0.5f * kTrack_m + 0.1f;
    push_back_across_edges(pose_.position,
                           {fwd * front - right * side, fwd * front + right * side, fwd * rear - right * side,
                            fwd * rear + right * side},
                           drivable, [&](glm::vec2 offset, glm::vec2 normal) { touch(offset, normal); });
}

void Car::touch(glm::vec2 offset, glm::vec2 normal) {
    // In the car's frame (x forward, y left) a point at (px, py) moves at
    // (u - r py, v + r px). Slow, the tyres hold the rear axle from sliding sideways
    // (v = b r), so a push on the nose mostly pivots the car about its rear axle; faster,
    // the body is free in the plane and the tyres sort it out afterwards.
    const glm::vec3 fwd3 = pose_.forward_flat(), right3 = pose_.right_flat();
    const glm::vec2 fwd(fwd3.x, fwd3.z), left(-right3.x, -right3.z);
    auto local = [&](glm::vec2 w) { return glm::vec2(w.x * fwd.x + w.y * fwd.y, w.x * left.x + w.y * left.y); };
    const glm::vec2 p = local(offset);
    const float b = p_.cg_to_rear_m, m = p_.mass_kg, inertia = p_.yaw_inertia_kgm2;
    const bool pivoting = std::fabs(u_) < 2.0f;
    auto speed_along = [&](glm::vec2 d) { return (u_ - r_ * p.y) * d.x + (v_ + r_ * p.x) * d.y; };
    auto inverse_mass = [&](glm::vec2 d) {
        if (pivoting) {
            float arm = -p.y * d.x + (b + p.x) * d.y;
            return d.x * d.x / m + arm * arm / (m * b * b + inertia);
        }
        float arm = -p.y * d.x + p.x * d.y;
        return (d.x * d.x + d.y * d.y) / m + arm * arm / inertia;
    };
    auto push = [&](glm::vec2 d, float j) {
        if (pivoting) {
            u_ += j * d.x / m;
            r_ += j * (-p.y * d.x + (b + p.x) * d.y) / (m * b * b + inertia);
            v_ = b * r_;
        } else {
            u_ += j * d.x / m;
            v_ += j * d.y / m;
            r_ += j * (-p.y * d.x + p.x * d.y) / inertia;
        }
    };
    const glm::vec2 n = local(normal), t(-n.y, n.x);
    scraping_s_ = kScrapeHold_s;
    float into = speed_along(n);
    if (into >= 0.0f) return;
    float j = -(1.0f + kScrape.restitution) * into / inverse_mass(n);
    if (j > touch_impulse_ns_) {
        touch_impulse_ns_ = j;
        touch_offset_ = offset;
    }
    push(n, j);
    float jt = std::clamp(-speed_along(t) / inverse_mass(t), -kScrape.friction * j, kScrape.friction * j);
    push(t, jt);
}

bool Car::fits(const Terrain& terrain, glm::vec2 xz, float heading_rad) const {
    Pose at;
    at.heading_rad = heading_rad;
    glm::vec3 fwd = at.forward_flat(), right = at.right_flat();
    float y = terrain.support_height(xz, terrain.ground_height(xz), kMaxStep_m);
    for (float along : {p_.cg_to_front_m, -p_.cg_to_rear_m}) {
        glm::vec2 c = xz + glm::vec2(fwd.x, fwd.z) * along;
        if (terrain.resolve_solids(c, p_.radius_m, y + 0.25f, y + p_.height_m)) return false;
    }
    for (float along : {p_.cg_to_front_m + 0.8f, -p_.cg_to_rear_m - 0.8f})
        for (float side : {-0.5f * kTrack_m - 0.1f, 0.5f * kTrack_m + 0.1f}) {
            glm::vec2 c = xz + glm::vec2(fwd.x * along + right.x * side, fwd.z * along + right.z * side);
            float ground = terrain.support_height(c, y, kMaxStep_m);
            if (!terrain.inside_world(c) || ground < terrain.level().sea_level_m + 0.1f || ground > y + kMaxStep_m)
                return false;
        }
    return true;
}

void Car::reset(const Terrain& terrain) {
    // The nearest road's middle line, heading along it the way the car faced most; then
    // the nearest free spot along that line. Without a road that fits, the spawn point.
    const LevelDesc& level = terrain.level();
    glm::vec2 here(pose_.position.x, pose_.position.z);
    glm::vec2 spot(level.car_spawn.position.x, level.car_spawn.position.z);
    float heading = level.car_spawn.heading_rad;
    float best = -1.0f;
    glm::vec3 fwd = pose_.forward_flat();
    for (const Rect& road : level.roads) {
        glm::vec2 size = road.max - road.min;
        bool along_x = size.x >= size.y;
        glm::vec2 mid = 0.5f * (road.min + road.max);
        glm::vec2 axis = along_x ? glm::vec2(1.0f, 0.0f) : glm::vec2(0.0f, 1.0f);
        float lo = along_x ? road.min.x : road.min.y, hi = along_x ? road.max.x : road.max.y;
        float t0 = std::clamp(along_x ? here.x : here.y, lo, hi);
        // Facing +x is heading 0, facing +z is heading -pi/2 (Pose).
        float dir = axis.x * fwd.x + axis.y * fwd.z >= 0.0f ? 1.0f : -1.0f;
        float road_heading = along_x ? (dir > 0.0f ? 0.0f : 3.14159265f) : (dir > 0.0f ? -1.5707963f : 1.5707963f);
        for (int k = 0; k <= 2 * kResetTries; ++k) {
            float t = t0 + kResetStep_m * float((k + 1) / 2) * (k % 2 == 1 ? 1.0f : -1.0f);
            if (t < lo || t > hi) continue;
            glm::vec2 c = along_x ? glm::vec2(t, mid.y) : glm::vec2(mid.x, t);
            glm::vec2 d = c - here;
            float dist2 = d.x * d.x + d.y * d.y;
            if (best >= 0.0f && dist2 >= best) continue;
            if (!fits(terrain, c, road_heading)) continue;
            best = dist2;
            spot = c;
            heading = road_heading;
        }
    }
    pose_ = Pose{};
    pose_.position = {spot.x, terrain.support_height(spot, terrain.ground_height(spot), kMaxStep_m), spot.y};
    pose_.heading_rad = heading;
    u_ = v_ = r_ = steer_ = scraping_s_ = 0.0f;
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


}  // namespace sim
