#include "effects/scene/SkyOcclusionPass.h"

#include "effects/gl/PipelineState.h"

namespace effects {

SkyOcclusionPass::SkyOcclusionPass()
    : program_(gl::Program::from_files("sky_occlusion", {"scene/shadow.vert.glsl", "scene/depth_only.frag.glsl"})),
      fbo_(gl::Framebuffer::create("sky_occlusion")) {}

void SkyOcclusionPass::render(const FrameContext& frame) {
    if (drawn_) return;
    drawn_ = true;
    SceneLighting& lighting = frame.lighting;
    const SceneGeometry& geometry = frame.resources.geometry;
    const glm::vec3 lo = geometry.props_min(), hi = geometry.props_max();
    if (!(hi.x > lo.x && hi.z > lo.z)) return;  // no props: nothing above anything

    fbo_.attach_depth(lighting.sky_map);
    fbo_.set_draw_buffers({});
    fbo_.check_complete();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    const int size = lighting.sky_map.width();
    glViewport(0, 0, size, size);
    // Nothing culled: roofs are seen from above and below alike.
    gl::PipelineScope state({.depth_test = true, .depth_write = true});
    glClear(GL_DEPTH_BUFFER_BIT);
    program_.use();
    program_.set("u_view_proj", frame.data.sky_occlusion_view_proj);
    geometry.draw_props(program_, true);
}

}  // namespace effects
