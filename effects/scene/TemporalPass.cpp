#include "effects/scene/TemporalPass.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/PipelineState.h"

namespace effects {

namespace {

float radical_inverse(uint64_t i, uint64_t base) {
    float result = 0.0f, digit = 1.0f / float(base);
    for (; i > 0; i /= base, digit /= float(base)) result += float(i % base) * digit;
    return result;
}

}  // namespace

glm::vec2 temporal_jitter_px(uint64_t frame) {
    const uint64_t i = frame % 8 + 1;  // Halton's point 0 is the pixel's corner
    return {radical_inverse(i, 2) - 0.5f, radical_inverse(i, 3) - 0.5f};
}

TemporalPass::TemporalPass()
    : program_(gl::Program::from_files("temporal", {"common/fullscreen.vert.glsl", "scene/temporal.frag.glsl"})),
      from_hdr_(gl::Program::from_files("temporal.hdr", {"common/fullscreen.vert.glsl", "scene/temporal.frag.glsl"},
                                        {"FROM_HDR"})) {}

void TemporalPass::register_params(ParamRegistry& params) {
    params.add("temporal", "this frame's weight", &current_weight_, 0.05f, 1.0f);
}

void TemporalPass::render(const FrameContext& frame) {
    if (!frame.resources.quality.temporal) {
        has_history_ = false;
        return;
    }
    SceneTargets& t = frame.targets;
    t.start_history_frame();
    // A resize made new (empty) images: the first frame after it starts afresh.
    const bool history = has_history_ && history_generation_ == t.generation();
    const Camera& camera = frame.camera;
    const glm::mat4 unjittered =
        glm::translate(glm::mat4(1.0f), glm::vec3(-camera.jitter_ndc, 0.0f)) * camera.view_proj;
    // The vehicle nearest the eye (the one the camera rides or follows) moves with its
    // pose, not with the world: its pixels' last place is through its last pose.
    const sim::Pose& ridden = glm::distance(frame.poses.car.position, camera.eye) <=
                                      glm::distance(frame.poses.boat.position, camera.eye)
                                  ? frame.poses.car
                                  : frame.poses.boat;
    const glm::mat4 vehicle = ridden.matrix();
    const glm::mat4 last_vehicle = history ? last_vehicle_ : vehicle;

    t.history_fbo().bind();
    glViewport(0, 0, t.width(), t.height());
    gl::PipelineScope state(gl::kFullScreen);
    const bool from_hdr = tonemapped_by_temporal(frame.resources.quality);
    const gl::Program& program = from_hdr ? from_hdr_ : program_;
    program.use();
    program.set("u_current", 0);
    program.set("u_history", 1);
    program.set("u_depth", 2);
    if (from_hdr) program.set("u_exposure", frame.resources.exposure);
    // From this frame's window position and depth (drawn jittered) to where that point
    // was in the last frame's unjittered view: as a still part of the world, or as a
    // point on the vehicle; what else moves (thrown objects, water) is left to the clamp.
    program.set("u_reproject", last_view_proj_ * camera.inv_view_proj);
    program.set("u_reproject_vehicle", last_view_proj_ * last_vehicle * glm::inverse(vehicle) * camera.inv_view_proj);
    program.set("u_current_weight", history ? current_weight_ : 1.0f);
    (from_hdr ? t.colour() : frame.resources.quality.antialias ? t.antialiased() : t.display()).bind(0);
    t.previous_history().bind(1);
    t.depth().bind(2);
    gl::bind_empty_vertex_array();
    glDrawArrays(GL_TRIANGLES, 0, 3);

    last_view_proj_ = unjittered;
    last_vehicle_ = vehicle;
    has_history_ = true;
    history_generation_ = t.generation();
}

}  // namespace effects
