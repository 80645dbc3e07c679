#pragma once
// What the energy pass reads from the sim: every segment of every shot in flight,
// and each shot as one line light (tail to head) for the surfaces around it.
#include <vector>

#include <glm/vec3.hpp>

#include "sim/weapon/EnergySegment.h"
#include "sim/world/World.h"

namespace effects {

struct EnergyBeamLight {
    glm::vec3 tail{0.0f}, head{0.0f};
    float strength = 0.0f;  // the shot's segment strength (fades with it)
};

struct EnergyView {
    std::vector<sim::EnergySegment> segments;
    std::vector<EnergyBeamLight> lights;
};

// Fills `view` from the world's weapon (empty without one). Reuses its storage.
void gather_energy_view(const sim::World& world, EnergyView& view);

}  // namespace effects
