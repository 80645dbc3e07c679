#include "effects/scene/FxaaPass.h"

#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/PipelineState.h"

namespace effects {

FxaaPass::FxaaPass()
    : program_(gl::Program::from_files("fxaa", {"common/fullscreen.vert.glsl", "scene/fxaa.frag.glsl"})) {}

void FxaaPass::register_params(ParamRegistry& params) {
    params.add("fxaa", "subpixel", &subpixel_, 0.0f, 1.0f);
    params.add("fxaa", "edge threshold", &threshold_, 0.05f, 0.5f);
    params.add("fxaa", "edge threshold floor", &threshold_min_, 0.0f, 0.2f);
}

void FxaaPass::render(const FrameContext& frame) {
    if (!frame.resources.quality.antialias) return;
    SceneTargets& t = frame.targets;
    if (t.width() == frame.output.width && t.height() == frame.output.height && !frame.resources.quality.temporal)
        glBindFramebuffer(GL_FRAMEBUFFER, frame.output.framebuffer);
    else
        t.antialiased_fbo().bind();
    glViewport(0, 0, t.width(), t.height());
    gl::PipelineScope state(gl::kFullScreen);
    program_.use();
    program_.set("u_display", 0);
    program_.set("u_subpixel", subpixel_);
    program_.set("u_threshold", threshold_);
    program_.set("u_threshold_min", threshold_min_);
    t.display().bind(0);
    gl::bind_empty_vertex_array();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace effects
