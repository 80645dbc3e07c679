#include "effects/scene/OpaquePass.h"

#include <string>
#include <vector>

#include "effects/gl/EmptyVertexArray.h"

namespace effects {

OpaquePass::OpaquePass()
    : sky_(gl::Program::from_files("opaque.sky", {"common/fullscreen.vert.glsl", "scene/sky.frag.glsl"})) {}

void OpaquePass::build_mesh_programs(const QualitySettings& quality) {
    const std::vector<std::string_view> files = {"scene/mesh.vert.glsl", "scene/mesh.frag.glsl"};
    std::vector<std::string> defines = lighting_defines(quality);
    defines.push_back(std::string("GROUND_DETAIL ") + (quality.ground_detail ? "1" : "0"));
    objects_ = gl::Program::from_files("opaque.objects", files, defines);
    defines.push_back("GROUND");
    ground_ = gl::Program::from_files("opaque.ground", files, defines);
    built_for_ = quality;
}

void OpaquePass::render(const FrameContext& frame) {
    if (built_for_ != frame.scene.quality) build_mesh_programs(frame.scene.quality);
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
    for (const gl::Program* p : {&objects_, &ground_}) {
        frame.scene.lighting.apply(*p);
        p->set("u_view_proj", frame.camera.view_proj);
        p->set("u_eye", frame.camera.eye);
    }
    frame.scene.geometry.apply_ground(ground_);
    frame.scene.geometry.draw(objects_, ground_, frame.poses, SceneGeometry::Use::Shading,
                              Frustum(frame.camera.view_proj));
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
