#include "effects/rain/DropHeightMap.h"

#include "effects/gl/PipelineState.h"

namespace effects {

DropHeightMap::DropHeightMap(int width, int height)
    : width_(width),
      height_(height),
      splat_(gl::Program::from_files("rain.splat", {"rain/splat.vert.glsl", "rain/splat.frag.glsl"})),
      shape_(gl::Program::from_files("rain.shape", {"rain/tiles.vert.glsl", "rain/shape.frag.glsl"})),
      normals_(gl::Program::from_files("rain.normals", {"rain/tiles.vert.glsl", "rain/normals.frag.glsl"})),
      mark_(gl::Program::from_files("rain.mark", {"rain/tiles.vert.glsl", "rain/mark.frag.glsl"})),
      vao_(gl::VertexArray::create("rain.splat")) {
    sums_ = gl::Texture::create_2d("rain.sums", GL_RGBA16F, width, height);
    surface_ = gl::Texture::create_2d("rain.surface", GL_RGBA16F, width, height);
    heights_ = gl::Texture::create_2d("rain.heights", GL_R32F, width, height);
    for (gl::Texture* t : {&sums_, &heights_, &surface_}) {
        t->set_filter(GL_LINEAR, GL_LINEAR);
        t->set_wrap(GL_CLAMP_TO_EDGE);
    }
    sums_fbo_ = gl::Framebuffer::create("rain.sums");
    sums_fbo_.attach_colour(0, sums_);
    wet_depth_ = gl::Texture::create_2d("rain.wet_depth", GL_DEPTH_COMPONENT16, width, height);
    sums_fbo_.attach_depth(wet_depth_);
    sums_fbo_.check_complete();
    heights_fbo_ = gl::Framebuffer::create("rain.heights");
    heights_fbo_.attach_colour(0, heights_);
    heights_fbo_.check_complete();
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

    gl::PipelineScope state(gl::kFullScreen);
    glViewport(0, 0, width_, height_);

    // 1. Splat: additive sums, where water can be only: the wet tiles are marked in the
    // depth buffer and the splats fail the depth test elsewhere (no pass reads there).
    glBindFramebuffer(GL_FRAMEBUFFER, sums_fbo_.id());
    const float zero[4] = {0, 0, 0, 0}, unmarked = 0.0f;
    glClearBufferfv(GL_COLOR, 0, zero);
    if (!metaballs.empty()) {
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
        gl::apply(gl::kFullScreen);
    }

    // 2. Threshold and height (compressed if asked) per texel where water can be.
    glBindFramebuffer(GL_FRAMEBUFFER, heights_fbo_.id());
    shape_.use();
    shape_.set("u_sums", 0);
    shape_.set("u_threshold", c.threshold);
    shape_.set("u_first_level", c.first_level);
    shape_.set("u_level_step", c.level_step);
    shape_.set("u_steps", c.steps);
    shape_.set("u_k", c.k);
    sums_.bind(0);
    wet_.draw(shape_);

    // 3. Normals, there too: a dry neighbour's height is the cleared 0.
    glBindFramebuffer(GL_FRAMEBUFFER, surface_fbo_.id());
    normals_.use();
    normals_.set("u_heights", 0);
    normals_.set("u_texel_mm", glm::vec2(glass_size_m.x * 1000.0f / float(width_), glass_size_m.y * 1000.0f / float(height_)));
    heights_.bind(0);
    wet_.draw(normals_);
}

}  // namespace effects
