#pragma once
// A uniform particle of water in the wipers' particle model (docs/effects/rain.md, "What is implemented").
#include <cstdint>

#include <glm/vec2.hpp>

namespace sim {

struct WaterParticle {
    glm::vec2 pos_m{0.0f};
    float mass_mg = 0.0f;
    uint32_t dead = 0;
};
static_assert(sizeof(WaterParticle) == 16, "WaterParticle is hashed as raw words");

}  // namespace sim
