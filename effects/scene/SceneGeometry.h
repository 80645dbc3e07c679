#pragma once
// Everything opaque in the level: terrain, props, the car, the boat and the thrown
// objects, drawn the same way by the shadow and the opaque passes.
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "effects/gl/Program.h"
#include "effects/scene/FramePoses.h"
#include "effects/scene/Frustum.h"
#include "effects/scene/GpuModel.h"
#include "effects/scene/GpuTerrain.h"
#include "effects/scene/SceneDesc.h"
#include "effects/scene/StaticBatches.h"
#include "sim/world/World.h"

namespace effects {

// The world-space box around a model's bounds placed by `transform`.
std::pair<glm::vec3, glm::vec3> world_box(const Model& m, const glm::mat4& transform);

class SceneGeometry {
public:
    SceneGeometry(const SceneDesc& desc, const sim::Terrain& terrain);

    // What a draw is for: shading (the terrain through `ground`, the rest through
    // `objects`; sets u_model, u_normal_matrix, u_tint and the materials per draw), or
    // the sun's shadow casters (depth only, one program): those that stay put (props and
    // the ground's relief; level ground is left out) or those that move (vehicles,
    // thrown objects).
    enum class Use { Shading, StillShadowCasters, MovingShadowCasters };
    // Which world-space boxes a draw keeps (a vehicle is one box, the ground a box per
    // tile): all when empty.
    using Select = std::function<bool(glm::vec3 lo, glm::vec3 hi)>;
    // Whether the car is drawn: the rear-view mirror (MirrorPass) looks out of it.
    enum class Car { Drawn, LeftOut };
    // What `view` can see (and `select` keeps), nearest kinds first (the vehicles, thrown
    // objects, props, then the ground) so that the early depth test spares hidden pixels
    // their shading; given the `eye`, the vehicles' parts nearest it first too
    // (GpuModel::draw_parts). Shading the car, sets u_cabin_lining per mesh
    // (mesh.frag.glsl) and leaves it 0. The props are drawn merged (StaticBatches):
    // `select` and `view` keep or leave a batch (a material's meshes in a square) whole.
    // `open_sky_ground`: `ground` without the sky-occlusion lookup, for the tiles with
    // nothing above them (GpuTerrain::draw), its uniforms set as `ground`'s.
    void draw(const gl::Program& objects, const gl::Program& ground, const FramePoses& poses, Use use,
              const Frustum& view, const Select& select = {}, Car car = Car::Drawn,
              const std::optional<glm::vec3>& eye = std::nullopt, const gl::Program* open_sky_ground = nullptr) const;
    // World boxes holding everything a MovingShadowCasters draw can draw for `poses`
    // (the car and the boat with room for their turning wheels, thrown objects, markers).
    std::vector<std::pair<glm::vec3, glm::vec3>> moving_caster_boxes(const FramePoses& poses) const;
    // The car's or the boat's model whole at `pose` (its moving parts at rest): the
    // ghost (GhostPass). Sets u_model and u_normal_matrix.
    void draw_vehicle(const gl::Program& program, sim::Vehicle vehicle, const sim::Pose& pose) const;
    // The level's props alone: what stays put, for the top-down sky occlusion.
    void draw_props(const gl::Program& program, bool depth_only) const;
    // World-space bounds of the props (min = max = 0 without any).
    glm::vec3 props_min() const { return props_min_; }
    glm::vec3 props_max() const { return props_max_; }
    // Uniforms the ground shader needs (roads, shore), and how many roads it draws: its
    // ROAD_COUNT, compiled in so that the loop over them unrolls (a software rasteriser
    // reads a uniform array at a varying index lane by lane).
    void apply_ground(const gl::Program& program) const;
    int ground_road_count() const;
    const GpuModel& sea() const { return sea_; }
    // The ground's level of detail per tile for the next frame (GpuTerrain::plan), once
    // a frame before its passes, from the frame's eye and its scene's pixels per radian
    // (viewport height / (2 tan(fov_y / 2))); every draw of the frame follows it.
    void plan_terrain(glm::vec3 eye, float pixels_per_radian);
    // Counts the plans that changed a tile's level: what a cache of the ground keys on.
    uint64_t terrain_generation() const { return terrain_generation_; }

private:
    // The car, the boat and the thrown objects.
    void draw_moving(const gl::Program& program, const FramePoses& poses, bool depth_only, const Frustum& view,
                     const Select& select, Car car, const std::optional<glm::vec3>& eye) const;
    // The objectives' gates and targets: they change with the tick, so they cast their
    // shadows with what moves.
    void draw_markers(const gl::Program& program, const FramePoses& poses, bool depth_only, const Frustum& view,
                      const Select& select) const;

    const SceneDesc& desc_;
    const sim::LevelDesc& level_;
    std::vector<std::unique_ptr<GpuModel>> models_;
    GpuTerrain terrain_;
    uint64_t terrain_generation_ = 0;
    GpuModel sea_, sphere_;
    // The markers' shapes, plain and giving off light: the next gate amber, a hit buoy green.
    GpuModel box_, next_box_, hit_sphere_;
    glm::vec3 props_min_{0.0f}, props_max_{0.0f};
    StaticBatches batches_;  // the props merged, for draws that keep all the view sees
};

}  // namespace effects
