#pragma once
// Everything opaque in the level: terrain, props, the car, the boat and the thrown
// objects, drawn the same way by the shadow and the opaque passes.
#include <memory>
#include <vector>

#include "effects/gl/Program.h"
#include "effects/scene/GpuModel.h"
#include "effects/scene/SceneDesc.h"
#include "sim/world/World.h"

namespace effects {

class SceneGeometry {
public:
    SceneGeometry(const SceneDesc& desc, const sim::Terrain& terrain);

    // Sets u_model (and u_tint, u_surface unless depth_only) per draw.
    void draw(const gl::Program& program, const sim::World& world, bool depth_only) const;
    // The level's props alone: what stays put, for the top-down sky occlusion.
    void draw_props(const gl::Program& program, bool depth_only) const;
    // World-space bounds of the props (min = max = 0 without any).
    glm::vec3 props_min() const { return props_min_; }
    glm::vec3 props_max() const { return props_max_; }
    // Uniforms the ground shader needs (roads, shore).
    void apply_ground(const gl::Program& program) const;
    const GpuModel& sea() const { return sea_; }

private:
    const SceneDesc& desc_;
    const sim::LevelDesc& level_;
    std::vector<std::unique_ptr<GpuModel>> models_;
    GpuModel terrain_, sea_, sphere_;
    glm::vec3 props_min_{0.0f}, props_max_{0.0f};
};

}  // namespace effects
