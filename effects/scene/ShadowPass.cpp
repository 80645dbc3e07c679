#include "effects/scene/ShadowPass.h"

#include "effects/gl/PipelineState.h"

namespace effects {

ShadowPass::ShadowPass()
    : program_(gl::Program::from_files("shadow", {"scene/shadow.vert.glsl", "scene/depth_only.frag.glsl"})),
      fbo_(gl::Framebuffer::create("shadow")) {}

void ShadowPass::render(const FrameContext& frame) {
    SceneLighting& lighting = frame.lighting;
    if (lighting.shadow_map.width() != frame.resources.quality.shadow_map_size) {
        lighting.resize_shadow_map(frame.resources.quality.shadow_map_size);
        fbo_initialised_ = false;
    }
    const int size = lighting.shadow_map.width();
    const glm::mat4& view_proj = frame.data.sun_shadow_view_proj;

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
    program_.set("u_view_proj", view_proj);
    const Frustum sun_view(view_proj);
    // What stays put (props, relief) is drawn once per view of the sun (and plan of the
    // ground's detail); each frame starts from a copy of it and adds what moves.
    const uint64_t terrain = frame.resources.geometry.terrain_generation();
    if (still_view_proj_ != view_proj || still_terrain_ != terrain) {
        glBindFramebuffer(GL_FRAMEBUFFER, still_fbo_.id());
        glClear(GL_DEPTH_BUFFER_BIT);
        frame.resources.geometry.draw(program_, program_, frame.poses, SceneGeometry::Use::StillShadowCasters, sun_view);
        still_view_proj_ = view_proj;
        still_terrain_ = terrain;
    }
    glCopyImageSubData(still_map_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, lighting.shadow_map.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       size, size, 1);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    frame.resources.geometry.draw(program_, program_, frame.poses, SceneGeometry::Use::MovingShadowCasters, sun_view);
}

}  // namespace effects
