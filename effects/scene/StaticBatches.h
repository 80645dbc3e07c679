#pragma once
// The level's props merged into few draws: built once at level load, each batch the
// meshes of one material within one square of the ground, their vertices in world space.
// A prop draw costs llvmpipe about the same set-up (uniforms, vertex shader launch,
// binning) whatever its size, and most props are a few dozen triangles: drawn one by
// one they cost the opaque pass about as much as its pixels at half the output's size.
#include <functional>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "effects/gl/Buffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/VertexArray.h"
#include "effects/scene/Frustum.h"
#include "effects/scene/SceneDesc.h"

namespace effects {

class StaticBatches {
public:
    // Each mesh goes to the batch of its material (roughness, metallic, emissive) and of
    // the `cell_m` square its world box's centre stands in.
    explicit StaticBatches(const SceneDesc& desc, float cell_m = kCellM);

    // The batches `view` can see and `select` keeps (by their world box; all when empty);
    // with `eye`, the nearest first (so the early depth test spares what they hide).
    // u_model and u_normal_matrix are the identity; the material uniforms are set unless
    // depth_only.
    void draw(const gl::Program& program, bool depth_only, const Frustum& view,
              const std::function<bool(glm::vec3, glm::vec3)>& select = {},
              const std::optional<glm::vec3>& eye = std::nullopt) const;
    size_t size() const { return batches_.size(); }

    // About the reach of the view's near props in a frame (a quay's stretch): smaller
    // squares cull closer and draw more often.
    static constexpr float kCellM = 40.0f;

private:
    struct Batch {
        GLsizei index_count = 0;
        size_t first_index = 0;
        float roughness = 0.8f, metallic = 0.0f;
        glm::vec3 emissive{0.0f};
        glm::vec3 lo{0.0f}, hi{0.0f};  // world space
    };
    gl::Buffer vertices_, indices_;
    gl::VertexArray vao_;
    std::vector<Batch> batches_;
};

}  // namespace effects
