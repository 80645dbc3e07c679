#include "sim/water/SprayParticles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/core/DetMath.h"
#include "sim/core/NumberText.h"

namespace sim {

namespace {

constexpr float kPi = 3.14159265f;
constexpr size_t kParallelFrom = 2048;  // fewer droplets are not worth waking the pool

static_assert(sizeof(SprayParticle) == 8 * sizeof(float), "SprayParticle is hashed as raw floats");

}  // namespace

SprayParticles::SprayParticles(const SprayParams& params) : p_(params) {
    auto refuse = [](const std::string& what) { throw std::invalid_argument("SprayParticles: " + what); };
    if (p_.max_particles > 1000000)
        refuse("max_particles must be at most 1000000, got " + std::to_string(p_.max_particles));
    if (!std::isfinite(p_.gravity_mps2) || p_.gravity_mps2 <= 0.0f)
        refuse("gravity_mps2 must be positive, got " + num(p_.gravity_mps2));
    if (!(p_.drag_m >= 0.0f && p_.drag_m <= 0.01f)) refuse("drag_m must be in [0, 0.01], got " + num(p_.drag_m));
    if (!(p_.speed_fraction >= 0.0f && p_.speed_fraction <= 10.0f))
        refuse("speed_fraction must be in [0, 10], got " + num(p_.speed_fraction));
    if (!std::isfinite(p_.ripple_depth_m) || p_.ripple_depth_m < 0.0f)
        refuse("ripple_depth_m must be >= 0, got " + num(p_.ripple_depth_m));
    if (!std::isfinite(p_.max_age_s) || p_.max_age_s <= 0.0f)
        refuse("max_age_s must be positive, got " + num(p_.max_age_s));
    particles_.reserve(p_.max_particles);
}

bool SprayParticles::emit(const SprayParticle& p) {
    if (particles_.size() >= p_.max_particles) return false;
    particles_.push_back(p);
    return true;
}

int SprayParticles::emit_splash(glm::vec3 centre, float ring_radius_m, glm::vec3 object_velocity, int count,
                                Rng& rng, std::optional<glm::vec2> ahead) {
    const glm::vec3 v = object_velocity;
    const float s = p_.speed_fraction * (ahead ? std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z)
                                               : std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z));
    const glm::vec3 carry = ahead ? glm::vec3(v.x, 0.0f, v.z) : glm::vec3(0.0f);
    int added = 0;
    for (int k = 0; k < count && particles_.size() < p_.max_particles; ++k) {
        const float u = rng.unit();
        glm::vec2 dir;
        if (ahead) {  // the front half, mostly to the sides: ahead turned by 30..90 degrees
            float phi = (u < 0.5f ? -1.0f : 1.0f) * (kPi / 6.0f + (kPi / 3.0f) * std::fabs(2.0f * u - 1.0f));
            glm::vec2 side(-ahead->y, ahead->x);
            dir = *ahead * det::cos(phi) + side * det::sin(phi);
        } else {
            float phi = 2.0f * kPi * u;
            dir = {det::cos(phi), det::sin(phi)};
        }
        const float a0 = rng.unit(), a1 = rng.unit(), a2 = rng.unit();
        const float out = s * (0.2f + 0.8f * a0);
        const float up = s * (ahead ? 0.45f + 0.45f * a1 : 0.5f + 0.5f * a1);
        const float sideways = s * (a2 - 0.5f) * 0.5f;
        SprayParticle p;
        p.position = {centre.x + dir.x * ring_radius_m, centre.y + 0.01f, centre.z + dir.y * ring_radius_m};
        p.velocity = carry + glm::vec3(dir.x * out - dir.y * sideways, up, dir.y * out + dir.x * sideways);
        p.radius_m = 0.008f + 0.017f * rng.unit();
        p.age_s = 0.0f;
        particles_.push_back(p);
        ++added;
    }
    return added;
}

void SprayParticles::move_range(size_t begin, size_t end, float dt, const WaveGrid& grid, float sea_level_m) {
    const float g = p_.gravity_mps2;
    for (size_t i = begin; i < end; ++i) {
        SprayParticle& p = particles_[i];
        p.velocity.y -= g * dt;
        // Implicit in the speed, so a fine drop at speed slows to rest at most, never reverses.
        const glm::vec3 w = p.velocity;
        const float speed = std::sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
        p.velocity *= 1.0f / (1.0f + p_.drag_m * speed * dt / std::max(p.radius_m, 1e-4f));
        p.position += p.velocity * dt;
        p.age_s += dt;
        uint8_t fate = 0;
        if (p.velocity.y < 0.0f && p.position.y < sea_level_m + grid.sample({p.position.x, p.position.z}))
            fate = 1;
        else if (p.age_s > p_.max_age_s)
            fate = 2;
        fate_[i] = fate;
    }
}

void SprayParticles::step(float dt, const WaveGrid& grid, float sea_level_m, std::vector<Ripple>& ripples,
                          JobPool* jobs) {
    const size_t n = particles_.size();
    fate_.resize(n);
    if (jobs && n >= kParallelFrom)
        jobs->parallel_for(n, [&](size_t b, size_t e) { move_range(b, e, dt, grid, sea_level_m); });
    else
        move_range(0, n, dt, grid, sea_level_m);
    // In order, on one thread: the same survivors and ripples for any thread count.
    size_t kept = 0;
    for (size_t i = 0; i < n; ++i) {
        if (fate_[i] == 1) ripples.push_back({{particles_[i].position.x, particles_[i].position.z}, p_.ripple_depth_m});
        if (fate_[i] != 0) continue;
        if (kept != i) particles_[kept] = particles_[i];
        ++kept;
    }
    particles_.resize(kept);
}


}  // namespace sim
