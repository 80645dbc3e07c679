#pragma once
// Particle layouts the sim creates (nothing is shipped as data): a tank filled from
// the floor up, and the seed's two benchmark scenes, "wave" (a dam break) and "step"
// (a flow over a step).
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/fluid/ParticleFluid.h"

namespace sim {

// Particles on the rest-spacing lattice (2 radii), layer by layer from the floor of
// [lo, hi), each jittered by a tenth of the spacing. Throws std::invalid_argument if
// `count` does not fit.
std::vector<glm::vec3> fill_block(glm::vec3 lo, glm::vec3 hi, float particle_radius_m, int count, uint64_t seed);

struct FluidScene {
    ParticleFluidParams params;
    std::vector<glm::vec3> particles;
    std::vector<FluidBox> boxes;
};

// A dam break: a column of `count` particles at one end of a long box.
FluidScene wave_scene(int count = 100000);
// A column flowing over a step along the floor.
FluidScene step_scene(int count = 50000);

}  // namespace sim
