#include "effects/scene/TonemapPass.h"

#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/PipelineState.h"
#include "effects/scene/TemporalPass.h"

namespace effects {

TonemapPass::TonemapPass()
    : program_(gl::Program::from_files("tonemap", {"common/fullscreen.vert.glsl", "scene/tonemap.frag.glsl"})) {}

void TonemapPass::render(const FrameContext& frame) {
    // Into the output at its own size; for a smaller scene, anti-aliasing or temporal
    // upsampling, into the display image that they or the upscale pass read.
    SceneTargets& t = frame.targets;
    const QualitySettings& q = frame.resources.quality;
    if (tonemapped_by_temporal(q)) return;
    if (t.width() == frame.output.width && t.height() == frame.output.height && !q.antialias && !q.temporal) {
        glBindFramebuffer(GL_FRAMEBUFFER, frame.output.framebuffer);
        glViewport(0, 0, frame.output.width, frame.output.height);
    } else {
        t.display_fbo().bind();
        glViewport(0, 0, t.width(), t.height());
    }
    gl::PipelineScope state(gl::kFullScreen);
    program_.use();
    program_.set("u_exposure", frame.resources.exposure);
    program_.set("u_hdr", 0);
    t.colour().bind(0);
    gl::bind_empty_vertex_array();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace effects
