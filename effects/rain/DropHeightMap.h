#pragma once
// The seed's 2D-metaball height map of the glass (specs/rain.md, "Height map"): each
// drop splatted additively as N(h) = 1 / (1 + (h/R)^4) from a precomputed profile,
// then, per texel, the part above T = 0.5 compressed in five steps (V0 = 0.5 .. 0.9,
// k = 0.3) and turned into a height and a normal. Next to the density it splats the
// density-weighted radius, so a texel knows how tall its drops are (a single drop's
// peak is as high as its radius, like the hemisphere it stands for).
#include <span>

#include <glm/vec2.hpp>

#include "effects/gl/Buffer.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/gl/VertexArray.h"
#include "effects/rain/RainView.h"

namespace effects {

struct HeightCompression {
    float threshold = 0.5f;  // T
    float first_level = 0.5f, level_step = 0.1f;  // V0 = 0.5, 0.6, ... 
    int steps = 5;
    float k = 0.3f;
};

class DropHeightMap {
public:
    DropHeightMap(int width, int height);

    // Splats the metaballs over a glass of glass_size_m (radii times radius_scale),
    // then compresses and takes normals. Leaves the GL viewport and framebuffer changed.
    void update(std::span<const RainMetaball> metaballs, glm::vec2 glass_size_m, float radius_scale,
                const HeightCompression& compression = {});

    // rg: the normal's u and v components (z is implied), b: height in mm, a: 1 on water.
    const gl::Texture& surface() const { return surface_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_, height_;
    gl::Texture profile_, surface_;
    gl::Texture density_;  // r: summed density, g: summed density times radius in mm
    gl::Framebuffer density_fbo_, surface_fbo_;
    gl::Program splat_, shape_;
    gl::VertexArray vao_;
    gl::Buffer instances_;
};

}  // namespace effects
