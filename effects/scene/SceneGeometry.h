#pragma once
// Everything opaque in the level: terrain, props, the car, the boat and the thrown
// objects, drawn the same way by the shadow and the opaque passes.
#include <memory>
#include <vector>

#include "effects/gl/Program.h"
#include "effects/scene/FramePoses.h"
#include "effects/scene/Frustum.h"
#include "effects/scene/GpuModel.h"
#include "effects/scene/SceneDesc.h"
#include "sim/world/World.h"

namespace effects {

class SceneGeometry {
public:
    SceneGeometry(const SceneDesc& desc, const sim::Terrain& terrain);

    // What a draw is for: shading (the terrain through `ground`, the rest through
    // `objects`; sets u_model, u_normal_matrix, u_tint and the materials per draw), or
    // the sun's shadow casters (depth only, one program; level ground is left out).
    enum class Use { Shading, ShadowCasters };
    // What `view` can see, nearest kinds first (the vehicles, thrown objects, props,
    // then the ground) so that the early depth test spares hidden pixels their shading.
    void draw(const gl::Program& objects, const gl::Program& ground, const FramePoses& poses, Use use,
              const Frustum& view) const;
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
    std::vector<std::pair<glm::vec3, glm::vec3>> prop_bounds_;  // world space, per instance
};

}  // namespace effects
