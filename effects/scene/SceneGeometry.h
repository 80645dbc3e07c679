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
    // Uniforms the ground shader needs (roads, shore).
    void apply_ground(const gl::Program& program) const;
    const GpuModel& sea() const { return sea_; }

private:
    const SceneDesc& desc_;
    const sim::LevelDesc& level_;
    std::vector<std::unique_ptr<GpuModel>> models_;
    GpuModel terrain_, sea_, sphere_;
};

}  // namespace effects
