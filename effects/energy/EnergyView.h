#pragma once
// What the energy pass reads from the sim: every segment of every shot in flight,
// and each shot as one line light (tail to head) for the surfaces around it.
#include <vector>

#include <glm/vec3.hpp>

#include "effects/scene/LineLight.h"
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

// How brightly and how far the beams light what is near them (the debug panel's
// "energy" group; docs/effects/energy.md).
struct BeamLighting {
    float intensity_per_strength = 60.0f;  // line-light intensity per unit of segment strength
    float reach_m = 9.0f;
};

// The line lights the beams in `view` make, one per shot from its tail to its head: the
// first kMaxLineLights (the shaders light with no more). Reuses `lights`' storage.
void beam_line_lights(const EnergyView& view, const BeamLighting& lighting, std::vector<LineLight>& lights);

}  // namespace effects
