#include "effects/rain/DropHeightMap.h"

#include "effects/gl/PipelineState.h"

namespace effects {

DropHeightMap::DropHeightMap(int width, int height)
    : width_(width),
      height_(height),
      splat_(gl::Program::from_files("rain.splat", {"rain/splat.vert.glsl", "rain/splat.frag.glsl"})),
      shape_(gl::Program::from_files("rain.shape", {"rain/tiles.vert.glsl", "rain/shape.frag.glsl"})),
      mark_(gl::Program::from_files("rain.mark", {"rain/tiles.vert.glsl", "rain/mark.frag.glsl"})),
      vao_(gl::VertexArray::create("rain.splat")) {
    sums_ = gl::Texture::create_2d("rain.sums", GL_RGBA16F, width, height);
    surface_ = gl::Texture::create_2d("rain.surface", GL_RGBA16F, width, height);
    for (gl::Texture* t : {&sums_, &surface_}) {
        t->set_filter(GL_LINEAR, GL_LINEAR);
        t->set_wrap(GL_CLAMP_TO_EDGE);
    }
    sums_fbo_ = gl::Framebuffer::create("rain.sums");
    sums_fbo_.attach_colour(0, sums_);
    wet_depth_ = gl::Texture::create_2d("rain.wet_depth", GL_DEPTH_COMPONENT16, width, height);
    sums_fbo_.attach_depth(wet_depth_);
    sums_fbo_.check_complete();
    surface_fbo_ = gl::Framebuffer::create("rain.surface");
    surface_fbo_.attach_colour(0, surface_);
    surface_fbo_.check_complete();
    vao_.attribute(0, 0, 4, GL_FLOAT, 0);
    vao_.binding_divisor(0, 1);
}

void DropHeightMap::update(std::span<const RainMetaball> metaballs, glm::vec2 glass_size_m, float radius_scale,
                           const HeightCompression& c) {
    if (gl::upload_growing(instances_, "rain.metaballs", std::as_bytes(metaballs)))
        vao_.vertex_buffer(0, instances_, 0, sizeof(RainMetaball));
    tiles_ = drops_by_tile(metaballs, glass_size_m, width_, height_, radius_scale, c.threshold);
    wet_.set(tiles_, width_, height_);
    glass_size_m_ = glass_size_m;
    compression_ = c;
    surface_made_ = false;

    gl::PipelineScope state(gl::kFullScreen);
    glViewport(0, 0, width_, height_);

    // Additive sums, where water can be only: the wet tiles are marked in the depth
    // buffer and the splats fail the depth test elsewhere (no texel there can reach T).
    glBindFramebuffer(GL_FRAMEBUFFER, sums_fbo_.id());
    const float zero[4] = {0, 0, 0, 0}, unmarked = 0.0f;
    glClearBufferfv(GL_COLOR, 0, zero);
    if (metaballs.empty()) return;
    gl::apply({.depth_write = true});  // a depth clear writes only through the depth mask
    glClearBufferfv(GL_DEPTH, 0, &unmarked);
    gl::apply({.depth_test = true, .depth_write = true, .depth_func = GL_ALWAYS, .colour_write = false});
    mark_.use();
    wet_.cover(mark_);  // at depth 0.5, as the splats
    gl::apply({.depth_test = true, .depth_func = GL_LEQUAL, .blend = gl::kAdd});
    splat_.use();
    splat_.set("u_glass_size_m", glass_size_m);
    splat_.set("u_radius_scale", radius_scale);
    splat_.set("u_reach", kMetaballReach);
    vao_.bind();
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(metaballs.size()));
}

void DropHeightMap::set_shape(const gl::Program& program) const {
    program.set("u_threshold", compression_.threshold);
    program.set("u_first_level", compression_.first_level);
    program.set("u_level_step", compression_.level_step);
    program.set("u_steps", compression_.steps);
    program.set("u_k", compression_.k);
    program.set("u_texel_mm", glm::vec2(glass_size_m_.x * 1000.0f / float(width_), glass_size_m_.y * 1000.0f / float(height_)));
}

const gl::Texture& DropHeightMap::surface() {
    if (surface_made_) return surface_;
    surface_made_ = true;
    gl::PipelineScope state(gl::kFullScreen);
    glViewport(0, 0, width_, height_);
    glBindFramebuffer(GL_FRAMEBUFFER, surface_fbo_.id());
    shape_.use();
    shape_.set("u_sums", 0);
    set_shape(shape_);
    sums_.bind(0);
    wet_.draw(shape_);
    return surface_;
}

}  // namespace effects
