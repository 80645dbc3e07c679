#include "effects/rain/ReferenceHeightMap.h"

#include "effects/gl/PipelineState.h"
#include "effects/rain/DropTiles.h"
#include "effects/rain/MetaballReference.h"

namespace effects {

ReferenceHeightMap::ReferenceHeightMap(int width, int height)
    : width_(width),
      height_(height),
      iso_(gl::Program::from_files("rain.reference", {"rain/tiles.vert.glsl", "rain/reference.frag.glsl"})),
      normals_(gl::Program::from_files("rain.normals", {"rain/tiles.vert.glsl", "rain/normals.frag.glsl"})) {
    heights_ = gl::Texture::create_2d("rain.reference.heights", GL_R32F, width, height);
    surface_ = gl::Texture::create_2d("rain.reference.surface", GL_RGBA16F, width, height);
    for (gl::Texture* t : {&heights_, &surface_}) {
        t->set_filter(GL_NEAREST, GL_NEAREST);
        t->set_wrap(GL_CLAMP_TO_EDGE);
    }
    heights_fbo_ = gl::Framebuffer::create("rain.reference.heights");
    heights_fbo_.attach_colour(0, heights_);
    heights_fbo_.check_complete();
    surface_fbo_ = gl::Framebuffer::create("rain.reference.surface");
    surface_fbo_.attach_colour(0, surface_);
    surface_fbo_.check_complete();
}

void ReferenceHeightMap::update(std::span<const RainMetaball> drops, glm::vec2 glass_size_m, float threshold) {
    const DropTiles tiles = drops_by_tile(drops, glass_size_m, width_, height_, 1.0f, threshold);
    gl::upload_growing(drops_, "rain.reference.drops", std::as_bytes(drops));
    gl::upload_growing(tiles_, "rain.reference.tiles", std::as_bytes(std::span(tiles.ranges)));
    gl::upload_growing(tile_drops_, "rain.reference.tile_drops", std::as_bytes(std::span(tiles.indices)));
    wet_.set(tiles, width_, height_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, drops_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, tiles_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, tile_drops_.id());

    gl::PipelineScope state(gl::kFullScreen);
    glViewport(0, 0, width_, height_);

    // 1. Iso-surface height per texel where water can be, as the 2D path does.
    const glm::vec2 texel_m = glass_size_m / glm::vec2(float(width_), float(height_));
    glBindFramebuffer(GL_FRAMEBUFFER, heights_fbo_.id());
    iso_.use();
    iso_.set("u_texel_m", texel_m);
    iso_.set("u_tile_texels", DropTiles::kTexels);
    iso_.set("u_tile_cols", tiles.cols);
    iso_.set("u_threshold", threshold);
    iso_.set("u_reach", kMetaballReach);
    iso_.set("u_ceiling_m", bisection_ceiling_m(drops));
    iso_.set("u_bisections", kReferenceBisections);
    wet_.draw(iso_);

    // 2. Normals.
    glBindFramebuffer(GL_FRAMEBUFFER, surface_fbo_.id());
    normals_.use();
    normals_.set("u_heights", 0);
    normals_.set("u_texel_mm", texel_m * 1000.0f);
    heights_.bind(0);
    wet_.draw(normals_);
}

}  // namespace effects
