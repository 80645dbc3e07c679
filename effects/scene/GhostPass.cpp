#include "effects/scene/GhostPass.h"

#include "effects/gl/PipelineState.h"

namespace effects {

GhostPass::GhostPass()
    : program_(gl::Program::from_files("ghost", {"scene/mesh.vert.glsl", "scene/ghost.frag.glsl"})) {}

void GhostPass::register_params(ParamRegistry& params) {
    params.add("ghost", "opacity", &opacity_, 0.0f, 1.0f);
    params.add("ghost", "rim", &rim_, 0.0f, 1.0f);
}

void GhostPass::render(const FrameContext& frame) {
    if (!frame.poses.ghost) return;
    SceneTargets& t = frame.targets;
    glBindFramebuffer(GL_FRAMEBUFFER, t.hdr().id());
    glViewport(0, 0, t.width(), t.height());
    program_.use();
    program_.set("u_view_proj", frame.camera.view_proj);
    program_.set("u_eye", frame.camera.eye);
    program_.set("u_ghost_tint", tint_);
    program_.set("u_opacity", opacity_);
    program_.set("u_rim", rim_);
    SceneLighting::apply_sky(program_, frame.data.sky);
    const FramePoses::Ghost& ghost = *frame.poses.ghost;
    // Its depth first, then its colour where that depth is its own nearest surface's.
    gl::PipelineScope depth({.depth_test = true, .depth_write = true, .cull_back_faces = true, .colour_write = false});
    frame.resources.geometry.draw_vehicle(program_, ghost.vehicle, ghost.pose);
    gl::apply({.depth_test = true,
               .depth_write = false,
               .depth_func = GL_LEQUAL,
               .blend = gl::kPremultipliedOver,
               .cull_back_faces = true});
    frame.resources.geometry.draw_vehicle(program_, ghost.vehicle, ghost.pose);
}

}  // namespace effects
