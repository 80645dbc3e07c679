#include "sim/fluid/FluidTank.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "sim/fluid/FluidScenes.h"
#include "sim/objects/ThrownObjects.h"
#include "sim/vehicle/Boat.h"
#include "sim/world/World.h"

namespace sim {

namespace {

constexpr float kGravity = 9.81f;
constexpr float kMaxTankAccel = 40.0f;  // a teleported boat must not blow the liquid out
constexpr float kWakeAccel = 0.05f;       // m/s^2 of tank motion that wakes a sleeping liquid
constexpr float kWakeSpeed = 0.05f;       // m/s of an object in or over the tank that wakes it
constexpr float kSleepMeanSpeed = 0.02f;  // m/s: below this on average the surface looks still
constexpr uint32_t kSleepAfterTicks = 30;

ParticleFluidParams fluid_params(const FluidTankDesc& d) {
    if (d.particle_count < 1 || d.particle_count > 200000)
        throw std::invalid_argument("fluid: particle_count must be 1..200000, got " + std::to_string(d.particle_count));
    ParticleFluidParams p;
    p.box_size_m = d.inner_size_m;
    p.ceiling_m = 2.0f * d.inner_size_m.y;
    p.particle_radius_m = d.particle_radius_m;
    p.solver_iterations = d.solver_iterations;
    p.body_neighbours = d.body_neighbours;
    p.validate();
    return p;
}

}  // namespace

FluidTank::FluidTank(const FluidTankDesc& desc, glm::vec3 tank_spot, uint64_t seed)
    : desc_(desc), spot_(tank_spot), fluid_(fluid_params(desc)) {
    const glm::vec3 s = desc.inner_size_m;
    fluid_.add_particles(fill_block({0.0f, 0.0f, 0.0f}, s, desc.particle_radius_m, desc.particle_count, seed));
    tank_to_world_ = glm::translate(glm::mat4(1.0f), spot_ - glm::vec3(0.5f * s.x, 0.0f, 0.5f * s.z));
}

void FluidTank::connect(const SubsystemLinks& links) {
    boat_ = links.may<Boat>();
    thrown_ = links.may<ThrownObjects>();
}

glm::mat4 FluidTank::pose() const {
    const glm::vec3 s = desc_.inner_size_m;
    const glm::mat4 corner = glm::translate(glm::mat4(1.0f), glm::vec3(-0.5f * s.x, 0.0f, -0.5f * s.z));
    if (desc_.on_boat)
        if (boat_)
            return boat_->pose().matrix() * glm::translate(glm::mat4(1.0f), kBoatDeckOffset) * corner;
    return glm::translate(glm::mat4(1.0f), spot_) * corner;
}

void FluidTank::step(StepContext& ctx) {
    tank_to_world_ = pose();
    const glm::vec3 origin(tank_to_world_[3]);
    // The tank's own acceleration from its last three origins; in its frame the liquid
    // feels gravity less that acceleration.
    glm::vec3 accel(0.0f);
    if (ticks_ >= 2) {
        accel = (origin - 2.0f * origin_prev_[0] + origin_prev_[1]) / (ctx.dt * ctx.dt);
        float a = std::sqrt(accel.x * accel.x + accel.y * accel.y + accel.z * accel.z);
        if (a > kMaxTankAccel) accel *= kMaxTankAccel / a;
    }
    origin_prev_[1] = ticks_ >= 1 ? origin_prev_[0] : origin;
    origin_prev_[0] = origin;
    ++ticks_;
    const glm::mat3 to_world(tank_to_world_);
    const glm::mat3 to_tank = glm::transpose(to_world);  // a rotation
    const glm::vec3 local_accel = to_tank * (glm::vec3(0.0f, -kGravity, 0.0f) - accel);

    spheres_.clear();
    objects_inside_ = 0;
    if (thrown_) {
        const glm::vec3 size = desc_.inner_size_m;
        for (const ThrownObject& o : thrown_->objects()) {
            const glm::vec3 local = to_tank * (o.position - origin);
            const float r = o.radius_m;
            if (local.x < -r || local.x > size.x + r || local.z < -r || local.z > size.z + r || local.y < -r ||
                local.y > 2.0f * size.y + r)
                continue;
            spheres_.push_back({local, to_tank * o.velocity, r});
            if (local.y < size.y) ++objects_inside_;
        }
    }
    const float tank_accel = std::sqrt(accel.x * accel.x + accel.y * accel.y + accel.z * accel.z);
    // Woken by tank motion or anything moving in or over it (a stone at rest on the
    // floor does not keep it awake).
    bool stirred = tank_accel > kWakeAccel;
    for (const FluidSphere& o : spheres_) stirred = stirred || glm::dot(o.velocity, o.velocity) > kWakeSpeed * kWakeSpeed;
    if (stirred) {
        asleep_ = false;
        calm_ticks_ = 0;
    }
    if (asleep_) return;
    fluid_.step(ctx.dt, local_accel, spheres_, ctx.jobs);
    // Calm: the mean particle speed, summed in index order (the same for any threads).
    float speed_sum = 0.0f;
    for (const glm::vec3& v : fluid_.velocities()) speed_sum += std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    const bool calm = speed_sum < kSleepMeanSpeed * float(fluid_.velocities().size());
    calm_ticks_ = calm ? calm_ticks_ + 1 : 0;
    asleep_ = calm_ticks_ >= kSleepAfterTicks;
}

std::vector<Aabb> tank_walls(const FluidTankDesc& desc, glm::vec3 spot) {
    if (!desc.enabled || desc.on_boat) return {};
    const float t = 0.02f;  // glass thickness
    const glm::vec3 h(0.5f * desc.inner_size_m.x, desc.inner_size_m.y, 0.5f * desc.inner_size_m.z);
    const glm::vec3 lo = spot - glm::vec3(h.x, 0.0f, h.z), hi = spot + h;
    return {
        {{lo.x - t, lo.y, lo.z - t}, {hi.x + t, hi.y, lo.z}},  // north
        {{lo.x - t, lo.y, hi.z}, {hi.x + t, hi.y, hi.z + t}},  // south
        {{lo.x - t, lo.y, lo.z}, {lo.x, hi.y, hi.z}},          // west
        {{hi.x, lo.y, lo.z}, {hi.x + t, hi.y, hi.z}},          // east
    };
}


}  // namespace sim
