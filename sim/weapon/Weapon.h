#pragma once
// The energy weapon as the sim sees it: shots made of segments that grow from a ball
// into a beam, travel, sway and fade, all from the shot's start, direction and age.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/geometric.hpp>

#include "sim/core/Rng.h"
#include "sim/world/Subsystem.h"

namespace sim {

// One segment of the field (see specs/energy.md): start M, unit direction D, length L,
// sphere strength a and beam strength b.
struct EnergySegment {
    glm::vec3 start{0.0f};
    glm::vec3 direction{1.0f, 0.0f, 0.0f};
    float length_m = 0.0f;
    float sphere_strength = 0.0f;
    float beam_strength = 0.0f;
};

struct Shot {
    static constexpr int kSegments = 4;
    glm::vec3 origin{0.0f};
    glm::vec3 direction{1.0f, 0.0f, 0.0f};
    float phase = 0.0f;  // random per shot: how it sways
    uint32_t age_ticks = 0;
    std::array<EnergySegment, kSegments> segments{};
};

struct WeaponParams {
    float speed_mps = 45.0f;
    float max_length_m = 14.0f;    // beam length once grown
    float growth_s = 0.6f;         // ball to full beam
    float life_s = 2.5f;
    float fade_s = 0.6f;
    float strength = 0.12f;
    float sway_m = 0.35f;
};

class Weapon final : public Subsystem {
public:
    static constexpr size_t kMaxShots = 8;

    explicit Weapon(uint64_t seed, WeaponParams params = {});

    std::string_view name() const override { return "weapon"; }
    void step(StepContext& ctx) override;
    uint64_t hash() const override;

    void fire(glm::vec3 origin, glm::vec3 direction);
    const std::vector<Shot>& shots() const { return shots_; }
    const WeaponParams& params() const { return p_; }

private:
    void shape(Shot& s, float dt) const;

    WeaponParams p_;
    Rng rng_;
    std::vector<Shot> shots_;
};

}  // namespace sim
