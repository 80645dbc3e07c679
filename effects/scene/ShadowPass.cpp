#include "effects/scene/ShadowPass.h"

#include "effects/gl/PipelineState.h"

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
    // In steps, so that the map of what stays put is drawn again only when a step is taken.
    centre.x = std::round(centre.x / kCentreStep_m) * kCentreStep_m;
    centre.z = std::round(centre.z / kCentreStep_m) * kCentreStep_m;

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
        still_map_ = gl::Texture::create_2d("sun.shadow_map.still", GL_DEPTH_COMPONENT32F, size, size);
        still_fbo_ = gl::Framebuffer::create("shadow.still");
        still_fbo_.attach_depth(still_map_);
        still_fbo_.set_draw_buffers({});
        still_fbo_.check_complete();
        still_view_proj_.reset();
        fbo_initialised_ = true;
    }
    glViewport(0, 0, size, size);
    // No polygon offset: its slope term grows without bound on faces edge-on to the sun
    // (the car's sides and windows), pushing them behind the road they shade, which drew
    // the car's shadow as streaks; GL 4.5 has no clamp for it. The receiver biases
    // instead, along its normal (sun_visibility in shaders/common/lighting.glsl).
    // Nothing culled: thin walls and open meshes must cast shadows too.
    gl::PipelineScope state({.depth_test = true, .depth_write = true});
    program_.set("u_view_proj", lighting.shadow_view_proj);
    const Frustum sun_view(lighting.shadow_view_proj);
    // What stays put (props, relief) is drawn once per view of the sun; each frame starts
    // from a copy of it and adds what moves.
    if (still_view_proj_ != lighting.shadow_view_proj) {
        glBindFramebuffer(GL_FRAMEBUFFER, still_fbo_.id());
        glClear(GL_DEPTH_BUFFER_BIT);
        frame.scene.geometry.draw(program_, program_, frame.poses, SceneGeometry::Use::StillShadowCasters, sun_view);
        still_view_proj_ = lighting.shadow_view_proj;
    }
    glCopyImageSubData(still_map_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, lighting.shadow_map.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       size, size, 1);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    frame.scene.geometry.draw(program_, program_, frame.poses, SceneGeometry::Use::MovingShadowCasters, sun_view);
}

}  // namespace effects
