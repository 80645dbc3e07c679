#include "effects/scene/UpscalePass.h"

#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/PipelineState.h"

namespace effects {

UpscalePass::UpscalePass()
    : program_(gl::Program::from_files("upscale", {"common/fullscreen.vert.glsl", "scene/upscale.frag.glsl"})) {}

void UpscalePass::register_params(ParamRegistry& params) {
    params.add("upscale", "edge steepening", &edge_, 0.0f, 1.0f);
}

void UpscalePass::render(const FrameContext& frame) {
    SceneTargets& t = frame.targets;
    const QualitySettings& q = frame.resources.quality;
    // At scale 1 the tone map or the anti-aliasing wrote the output, unless the temporal
    // resolve has the frame (then this is a copy).
    if (t.width() == frame.output.width && t.height() == frame.output.height && !q.temporal) return;
    glBindFramebuffer(GL_FRAMEBUFFER, frame.output.framebuffer);
    glViewport(0, 0, frame.output.width, frame.output.height);
    gl::PipelineScope state(gl::kFullScreen);
    program_.use();
    program_.set("u_display", 0);
    program_.set("u_edge", edge_);
    (q.temporal ? t.history() : q.antialias ? t.antialiased() : t.display()).bind(0);
    gl::bind_empty_vertex_array();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace effects
