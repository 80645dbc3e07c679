#pragma once
// What the fluid pass draws: the tank's pose and size, and the particles as world-space
// ellipsoids (Yu & Turk kernels) split into the liquid body and the splash.
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "sim/fluid/AnisotropicKernels.h"
#include "sim/world/World.h"

namespace sim {
class JobPool;
class ParticleFluid;
}

namespace effects {

struct FluidView {
    glm::mat4 tank_to_world{1.0f};
    glm::vec3 tank_size{0.0f};  // the glass box [0, size] in the tank frame; zero: no glass drawn
    float particle_radius_m = 0.03f;
    std::vector<sim::FluidEllipsoid> body, splash;
    bool empty() const { return body.empty() && splash.empty(); }
    // The last kernels (tank frame) and the positions they were built from: a resting
    // liquid, or several frames between two ticks, reuse them.
    std::vector<glm::vec3> kernel_positions;
    std::vector<sim::FluidEllipsoid> kernels;
};

// The anisotropy settings for a fluid of this particle radius (neighbourhood 2 h).
sim::AnisotropyParams anisotropy_for(float particle_radius_m);

// Builds the view of a particle fluid whose frame is placed by tank_to_world; `jobs`, if
// given, shares the kernels' rebuild among its threads.
void make_fluid_view(const sim::ParticleFluid& fluid, const glm::mat4& tank_to_world, glm::vec3 tank_size,
                     FluidView& out, sim::JobPool* jobs = nullptr);
// The world's tank, if it has one (false otherwise).
bool gather_fluid_view(const sim::World& world, FluidView& out, sim::JobPool* jobs = nullptr);

}  // namespace effects
