#pragma once
// Spray droplets thrown from a splash ring (seed 003, 4.3, eqs. 4.5-4.7): ballistic
// under gravity with quadratic air drag that grows as drops shrink; a droplet that
// lands on the water dies and leaves a small ripple for the wave grid.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/core/JobPool.h"
#include "sim/core/Rng.h"
#include "sim/core/StateArchive.h"
#include "sim/water/SplashSheet.h"
#include "sim/water/WaveGrid.h"

namespace sim {

struct SprayParams {
    size_t max_particles = 10000;
    float gravity_mps2 = 9.81f;
    // Quadratic drag against still air, a = -drag_m * |v| v / radius: for a sphere
    // 3 rho_air C_d / (8 rho_water) = 3 * 1.2 * 0.5 / 8000. Fine drops slow hard and
    // fall near where they left (terminal speed ~10 m/s at 5 mm); a boat's bow outruns them.
    float drag_m = 2.25e-4f;
    // Launch speed per unit of the seed's |Vx| + |Vy| + |Vz| of the object: a stone
    // entering at 12 m/s throws droplets at up to ~6 m/s, with the crown.
    float speed_fraction = 0.4f;
    float ripple_depth_m = 0.001f;   // wave-grid push where a droplet lands
    float max_age_s = 3.0f;          // droplets that never land (off the grid edge) go
};

struct SprayParticle {
    glm::vec3 position, velocity;
    float radius_m;
    float age_s;
};

class SprayParticles {
public:
    // Throws std::invalid_argument for absurd parameters (max_particles up to 1e6).
    explicit SprayParticles(const SprayParams& params = {});

    const std::vector<SprayParticle>& particles() const { return particles_; }
    const SprayParams& params() const { return p_; }
    uint64_t hash() const { return hash_state(*this); }
    template <class Archive> void describe(Archive& ar) {
        ar.size64(particles_);
        ar.words(particles_, 21);
    }

    // Adds one droplet; false (and nothing added) when max_particles are alive.
    bool emit(const SprayParticle& p);
    // Seed eqs. 4.5-4.7: `count` droplets on the ring of radius ring_radius_m around
    // `centre` (on the surface), each velocity component a random fraction of
    // S = |Vx| + |Vy| + |Vz| of the object (the seed sums signed components, which a
    // falling object makes near zero), turned into the spray's frame: outward
    // speed_fraction*S*(0.2 + 0.8 a0), upward speed_fraction*S*(0.5 + 0.5 a1) (the
    // upward and outward bias), sideways speed_fraction*S*(a2 - 0.5)/2. With `ahead`
    // (a moving bow) the rule holds in the bow's frame: S counts the object's speed once
    // (not its |x| + |z| split), drops leave the front half of the ring mostly to the
    // sides, low (the hull's sheet peels off at 25-40 degrees), and carry the object's
    // horizontal velocity, so they burst beside the bow rather than fly back past the
    // helm. Returns how many were added.
    int emit_splash(glm::vec3 centre, float ring_radius_m, glm::vec3 object_velocity, int count, Rng& rng,
                    std::optional<glm::vec2> ahead = std::nullopt);

    // Moves every droplet (in parallel over the pool when given: each droplet is
    // written by one thread), then removes in order the ones that landed (adding a
    // Ripple each) or grew too old.
    void step(float dt, const WaveGrid& grid, float sea_level_m, std::vector<Ripple>& ripples,
              JobPool* jobs = nullptr);
    void clear() { particles_.clear(); }

private:
    void move_range(size_t begin, size_t end, float dt, const WaveGrid& grid, float sea_level_m);

    SprayParams p_;
    std::vector<SprayParticle> particles_;
    std::vector<uint8_t> fate_;  // per droplet after a move: 0 flying, 1 landed, 2 expired
};

}  // namespace sim
