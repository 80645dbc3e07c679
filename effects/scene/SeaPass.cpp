#include "effects/scene/SeaPass.h"

namespace effects {

SeaPass::SeaPass() : program_(gl::Program::from_files("sea", {"scene/sea.vert.glsl", "scene/sea.frag.glsl"})) {}

void SeaPass::render(const FrameContext& frame) {
    SceneTargets& t = frame.scene.targets;
    glBindFramebuffer(GL_FRAMEBUFFER, t.scene().id());
    glViewport(0, 0, t.width(), t.height());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    program_.use();
    frame.scene.lighting.apply(program_);
    program_.set("u_view_proj", frame.camera.view_proj);
    program_.set("u_inv_proj", frame.camera.inv_proj);
    program_.set("u_eye", frame.camera.eye);
    program_.set("u_time_s", float(frame.time_s));
    program_.set("u_inv_viewport", glm::vec2(1.0f / float(t.width()), 1.0f / float(t.height())));
    program_.set("u_scene_colour", 0);
    program_.set("u_scene_depth", 1);
    t.colour_copy().bind(0);
    t.depth_copy().bind(1);
    frame.scene.geometry.sea().draw(program_, true);
}

}  // namespace effects
