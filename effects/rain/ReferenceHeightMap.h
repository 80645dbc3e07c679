#pragma once
// The 3D metaball reference (MetaballReference.h) on the GPU, so the fast 2D path can
// be timed against it in the same execution environment: per texel, the iso-surface
// height N = T of the same drops, kernel and cut-off, by the same bisection over the
// same per-tile drop lists (built on the CPU, drops_by_tile), then normals from the
// right and upper neighbours; both over the tiles where water can be only, like the
// 2D path (WetTiles). The CPU reference stays the oracle it is checked against.
#include <span>

#include <glm/vec2.hpp>

#include "effects/gl/Buffer.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/rain/RainView.h"
#include "effects/rain/WetTiles.h"

namespace effects {

class ReferenceHeightMap {
public:
    ReferenceHeightMap(int width, int height);

    // Leaves the GL viewport and framebuffer changed.
    void update(std::span<const RainMetaball> drops, glm::vec2 glass_size_m, float threshold = 0.5f);

    const gl::Texture& heights() const { return heights_; }  // R32F, mm; 0: dry
    const gl::Texture& surface() const { return surface_; }  // laid out as DropHeightMap::surface()
    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_, height_;
    gl::Texture heights_, surface_;
    gl::Framebuffer heights_fbo_, surface_fbo_;
    gl::Program iso_, normals_;
    gl::Buffer drops_, tiles_, tile_drops_;
    WetTiles wet_;
};

}  // namespace effects
