#pragma once
// Raindrops on the car's windshield and the wipers that clear them (seed 001, Goto,
// Tanaka, Sagawa; docs/effects/rain.md). Far from the blades drops follow the grid model:
// one drop per cell, moved cell by cell to one of the three cells ahead, chosen by
// affinity, merging, leaving trailing drops. Drops a blade touches become uniform
// particles that the blade pushes and that push each other; out of the band around
// the blade they become grid drops again, deferred while a big drop is near.
// Everything is in the glass's own coordinates (GlassSurface).
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/core/Rng.h"
#include "sim/rain/GlassSurface.h"
#include "sim/rain/ParticleCollider.h"
#include "sim/rain/RainParams.h"
#include "sim/rain/WaterParticle.h"
#include "sim/rain/WiperBlade.h"
#include "sim/rain/WiperMotor.h"
#include "sim/world/DescribedSubsystem.h"

namespace sim {

class Player;
class Car;
class Weather;

struct RainDrop {
    glm::vec2 pos_m{0.0f};    // glass coordinates, inside cell
    glm::vec2 vel_mps{0.0f};
    float mass_mg = 0.0f;
    float radius_m = 0.0f;    // RainSim::radius_m(mass_mg), kept with the mass
    float travel_m = 0.0f;    // run since the last cell step
    int32_t cell = 0;
    uint32_t flags = 0;       // kTrail, kDead
    static constexpr uint32_t kTrail = 1, kDead = 2;
    bool trail() const { return flags & kTrail; }
    bool dead() const { return flags & kDead; }
};
static_assert(sizeof(RainDrop) == 36, "RainDrop is hashed as raw words");

// Where the water went: what is on the glass is added - evaporated - drained, to
// rounding. Only trailing drops evaporate; drained water ran or was pushed off an edge.
struct RainLedger {
    double added_mg = 0.0, evaporated_mg = 0.0, drained_mg = 0.0;
};

// The forces of one tick in car model space (m/s^2): gravity plus the car's inertia,
// and the air flow's push on a drop of slide mass.
struct RainForces {
    glm::vec3 body{0.0f, -9.81f, 0.0f};
    glm::vec3 air{0.0f};
};

class RainSim final : public DescribedSubsystem<RainSim> {
public:
    // Throws std::invalid_argument naming the parameter for bad glass or parameters.
    RainSim(const RainParams& params, std::vector<glm::vec3> glass_lower, std::vector<glm::vec3> glass_upper,
            uint64_t seed);

    static constexpr std::string_view kName = "rain";
    std::string_view name() const override { return kName; }
    void connect(const SubsystemLinks& links) override;
    void step(StepContext& ctx) override;
    template <class Archive> void describe(Archive& ar) {
        ar.rng(rng_);
        ar.u64(tick_);
        ar.fields(motor_);
        for (WiperBlade& b : blades_) ar.fields(b);
        ar.raw(ledger_);
        ar.words(drops_);
        ar.words(particles_);
        ar.words(wet_tick_);
        ar.unhashed(cell_drop_);  // which drop each cell holds: follows from drops_
    }

    // One tick without a world: tests and the benchmark drive it directly.
    void advance(float intensity, WiperMode wipers, float car_speed_mps, const RainForces& forces, float dt);
    // Forces on the glass of a car at this speed, body acceleration (longitudinal,
    // lateral to the left) and world-to-model rotation of gravity.
    RainForces forces_for(float speed_mps, glm::vec2 accel_body_mps2, glm::vec3 gravity_model) const;

    // Places a drop (merging with one in its cell); counted as added. For tests.
    void add_drop(glm::vec2 pos_m, float mass_mg);

    const GlassSurface& glass() const { return glass_; }
    const RainParams& params() const { return p_; }
    const std::vector<RainDrop>& drops() const { return drops_; }
    const std::vector<WaterParticle>& particles() const { return particles_; }
    const std::array<WiperBlade, 2>& blades() const { return blades_; }
    const WiperMotor& motor() const { return motor_; }
    const RainLedger& ledger() const { return ledger_; }
    double mass_on_glass_mg() const;
    // How freshly a drop ran into a cell: 1 this tick, fading to 0 over wet_memory_s (the
    // memory that steers later drops; the renderer draws it as the streak a runner leaves).
    float wetness(int cell) const;
    // A drop's contact radius: a hemisphere of its volume.
    static float radius_m(float mass_mg);

private:
    void rain(float intensity, float car_speed_mps, float dt);
    void move_drops(const RainForces& forces, float dt);
    bool step_cell(size_t i);  // false when the drop left the glass
    void sweep(const WiperBlade& blade);
    void push_particles(bool carry);
    void particles_to_grid();
    void compact();
    float affinity(int cell) const;
    int32_t new_drop(glm::vec2 pos_m, float mass_mg, uint32_t flags);  // or merge; returns its index
    void kill_drop(size_t i);
    bool near_blade(glm::vec2 pos_m, float reach_m) const;

    RainParams p_;
    Rng rng_;
    GlassSurface glass_;
    WiperMotor motor_;
    std::array<WiperBlade, 2> blades_;
    std::vector<RainDrop> drops_;
    std::vector<WaterParticle> particles_;
    std::vector<int32_t> cell_drop_;     // drop index per cell, -1 for none
    std::vector<uint32_t> wet_tick_;     // tick + 1 a drop last ran into the cell, 0 never
    std::vector<uint8_t> heavy_;         // particles_to_grid: the cell's drop defers conversions
    RainLedger ledger_;
    uint32_t landed_ = 0;                // drops that reached the glass this tick (tick report; not hashed)
    uint64_t tick_ = 0;
    float particle_r_m_;
    float hold_ref_;                     // what holds a slide-mass drop, m/s^2
    float slide_r_m_;
    ParticleCollider collider_;          // scratch for the particle collisions

    // Connected at assembly (connect); nullptr where the world has none.
    const Player* player_ = nullptr;
    const Car* car_ = nullptr;
    const Weather* weather_ = nullptr;
};

}  // namespace sim
