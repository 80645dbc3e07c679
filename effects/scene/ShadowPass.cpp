#include "effects/scene/ShadowPass.h"

#include "effects/gl/PipelineState.h"
#include "effects/scene/ScreenRect.h"

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
        whole_copy_needed_ = true;
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
        whole_copy_needed_ = true;
    }
    // The map is the still map plus what moves: where last frame's moving casters drew
    // is restored from the still map, the rest is still right (a whole copy of a
    // 1024x1024 map costs llvmpipe about a third of a fill).
    auto copy = [&](glm::ivec4 r) {
        glCopyImageSubData(still_map_.id(), GL_TEXTURE_2D, 0, r.x, r.y, 0, lighting.shadow_map.id(), GL_TEXTURE_2D, 0,
                           r.x, r.y, 0, r.z - r.x, r.w - r.y, 1);
    };
    if (whole_copy_needed_) copy({0, 0, size, size});
    else
        for (const glm::ivec4& r : dirty_) copy(r);
    whole_copy_needed_ = false;
    dirty_.clear();
    for (const auto& [lo, hi] : frame.resources.geometry.moving_caster_boxes(frame.poses)) {
        // Orthographic: clip w is 1 everywhere, in front of any near plane at 0.5.
        const glm::ivec4 r = screen_rect_of_box(view_proj, 0.5f, lo, hi, size, size, 2);
        if (r.z > r.x && r.w > r.y) dirty_.push_back(r);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    frame.resources.geometry.draw(program_, program_, frame.poses, SceneGeometry::Use::MovingShadowCasters, sun_view);
}

}  // namespace effects
