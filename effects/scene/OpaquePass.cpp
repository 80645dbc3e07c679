#include "effects/scene/OpaquePass.h"

#include "effects/gl/EmptyVertexArray.h"

namespace effects {

OpaquePass::OpaquePass()
    : mesh_(gl::Program::from_files("opaque.mesh", {"scene/mesh.vert.glsl", "scene/mesh.frag.glsl"})),
      sky_(gl::Program::from_files("opaque.sky", {"common/fullscreen.vert.glsl", "scene/sky.frag.glsl"})) {}

void OpaquePass::render(const FrameContext& frame) {
    SceneTargets& t = frame.scene.targets;
    glBindFramebuffer(GL_FRAMEBUFFER, t.scene().id());
    glViewport(0, 0, t.width(), t.height());
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    const float clear_colour[4] = {0, 0, 0, 1}, clear_normal[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, clear_colour);
    glClearBufferfv(GL_COLOR, 1, clear_normal);
    glClear(GL_DEPTH_BUFFER_BIT);

    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    mesh_.use();
    frame.scene.lighting.apply(mesh_);
    frame.scene.geometry.apply_ground(mesh_);
    mesh_.set("u_view_proj", frame.camera.view_proj);
    mesh_.set("u_eye", frame.camera.eye);
    frame.scene.geometry.draw(mesh_, frame.world, false);
    glDisable(GL_CULL_FACE);

    // Sky last, only where nothing was drawn: the far plane passes GL_LEQUAL.
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    sky_.use();
    frame.scene.lighting.apply_sky(sky_);
    sky_.set("u_inv_view_proj", frame.camera.inv_view_proj);
    gl::bind_empty_vertex_array();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

}  // namespace effects
