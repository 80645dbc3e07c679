#include "effects/fluid/FluidView.h"

#include "sim/fluid/FluidTank.h"

namespace effects {

sim::AnisotropyParams anisotropy_for(float particle_radius_m) {
    sim::AnisotropyParams a;
    a.particle_radius_m = particle_radius_m;
    a.neighbourhood_m = 8.0f * particle_radius_m;  // twice the PBF kernel radius
    return a;
}

void make_fluid_view(const sim::ParticleFluid& fluid, const glm::mat4& tank_to_world, glm::vec3 tank_size,
                     FluidView& out, sim::JobPool* jobs) {
    out.tank_to_world = tank_to_world;
    out.tank_size = tank_size;
    out.particle_radius_m = fluid.params().particle_radius_m;
    if (fluid.positions() != out.kernel_positions || out.kernels.size() != fluid.positions().size()) {
        sim::anisotropic_kernels(fluid.positions(), anisotropy_for(out.particle_radius_m), out.kernels, jobs);
        out.kernel_positions = fluid.positions();
    }
    const std::vector<sim::FluidEllipsoid>& all = out.kernels;
    out.body.clear();
    out.splash.clear();
    const glm::mat3 rot(tank_to_world);
    for (size_t i = 0; i < all.size(); ++i) {
        sim::FluidEllipsoid e = all[i];
        e.centre = glm::vec3(tank_to_world * glm::vec4(e.centre, 1.0f));
        for (glm::vec3& a : e.axis) a = rot * a;
        (fluid.is_splash(i) ? out.splash : out.body).push_back(e);
    }
}

bool gather_fluid_view(const sim::World& world, FluidView& out, sim::JobPool* jobs) {
    const sim::FluidTank* tank = world.find<sim::FluidTank>();
    if (!tank) return false;
    make_fluid_view(tank->fluid(), tank->tank_to_world(), tank->inner_size(), out, jobs);
    return true;
}

}  // namespace effects
