#include "effects/scene/ShadowPass.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace effects {

ShadowPass::ShadowPass()
    : program_(gl::Program::from_files("shadow", {"scene/shadow.vert.glsl", "scene/shadow.frag.glsl"})),
      fbo_(gl::Framebuffer::create("shadow")) {}

void ShadowPass::register_params(ParamRegistry& params) {
    params.add("shadow", "half extent (m)", &half_extent_m_, 20.0f, 200.0f);
    params.add("shadow", "centre ahead (m)", &ahead_m_, 0.0f, 100.0f);
}

void ShadowPass::render(const FrameContext& frame) {
    SceneLighting& lighting = frame.scene.lighting;
    if (lighting.shadow_map.width() != frame.scene.quality.shadow_map_size) {
        lighting.resize_shadow_map(frame.scene.quality.shadow_map_size);
        fbo_initialised_ = false;
    }
    const int size = lighting.shadow_map.width();
    glm::vec3 view_dir = -glm::vec3(frame.camera.view[0][2], frame.camera.view[1][2], frame.camera.view[2][2]);
    glm::vec3 flat(view_dir.x, 0.0f, view_dir.z);
    float len = std::sqrt(flat.x * flat.x + flat.z * flat.z);
    glm::vec3 centre = frame.camera.eye + (len > 1e-3f ? flat / len : glm::vec3(0.0f)) * ahead_m_;
    centre.y = frame.world.level().land_height_m;

    glm::vec3 sun = lighting.sky.sun_dir;
    glm::vec3 up = std::fabs(sun.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    glm::mat4 view = glm::lookAt(centre + sun * 200.0f, centre, up);
    // Snap the centre to whole texels in light space.
    float texel = 2.0f * half_extent_m_ / float(size);
    glm::vec4 origin = view * glm::vec4(0, 0, 0, 1);
    glm::vec2 snap(std::round(origin.x / texel) * texel - origin.x, std::round(origin.y / texel) * texel - origin.y);
    view = glm::translate(glm::mat4(1.0f), glm::vec3(snap, 0.0f)) * view;
    glm::mat4 proj = glm::ortho(-half_extent_m_, half_extent_m_, -half_extent_m_, half_extent_m_, 1.0f, 420.0f);
    lighting.shadow_view_proj = proj * view;

    if (!fbo_initialised_) {
        fbo_ = gl::Framebuffer::create("shadow");
        fbo_.attach_depth(lighting.shadow_map);
        fbo_.set_draw_buffers({});
        fbo_.check_complete();
        fbo_initialised_ = true;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, size, size);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 2.0f);
    glDisable(GL_CULL_FACE);  // thin walls and open meshes must cast shadows too
    program_.set("u_view_proj", lighting.shadow_view_proj);
    frame.scene.geometry.draw(program_, program_, frame.poses, SceneGeometry::Use::ShadowCasters,
                              Frustum(lighting.shadow_view_proj));
    glDisable(GL_POLYGON_OFFSET_FILL);
}

}  // namespace effects
