#pragma once
// The seed's 2D-metaball height map of the glass (docs/effects/rain.md, "What is
// implemented"): each drop splatted additively as N(h) = 1 / (1 + (h/R)^4) from a
// precomputed profile, then per texel a height and a normal. Beside the summed density
// N the splat adds N^2 R, N^2 x^2 and N^2 (x = h/R), so a texel also knows the drop
// that dominates it: its radius and how far off its centre the texel is. The texel is
// then taken as that one 3D metaball, strong enough to give the summed density, and its
// height is where that ball's field falls to T. This is exact for a lone drop (a
// hemisphere of its radius) and for two equal drops meeting, and follows the CPU 3D
// reference (MetaballReference) to 2.9 degrees on the merged-drop scene.
//
// Per frame: clear and splat the sums (instanced quads, additive RGBA16F, depth-tested
// against the wet tiles marked in a depth buffer: 5-7% off the splat); then the
// height pass (to R32F) and the normals pass (one gather of the texel and its right
// and upper neighbours), both only over the tiles where water can be (drops_by_tile's
// `wet` runs, WetTiles), their targets cleared elsewhere. Measured under llvmpipe on
// the bench's merged-drop scene: 37% of the tiles, and the two passes cost 0.64 of
// full-screen ones (a texel costs more in small triangles than in one covering whole
// bins). Shading the two passes as one, from the sums at the three texels, gives the
// same surface bit for bit but costs about 1.6 times the separate passes (the branch
// for dry texels saves nothing there: every texel pays three fetches and heights).
// An octagon around the reach circle instead of the splat's square shades 17% fewer
// texels but measured slower (more, smaller triangles) and changes the sums' last bits.
//
// Deviation from the seed: its five-step compression (V0 = 0.5 .. 0.9, k = 0.3) stops
// the spikes of its height N - T at merged drops; this height has none, and the
// compression only flattens merged drops away from the 3D reference (2.9 -> 5.5 degrees,
// tests/rain_render_test.cpp). It stays available (HeightCompression::steps = 5; "height
// compression steps" under "rain" in the debug panel) but is off by default.
#include <span>

#include <glm/vec2.hpp>

#include "effects/gl/Buffer.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/gl/VertexArray.h"
#include "effects/rain/RainView.h"
#include "effects/rain/WetTiles.h"

namespace effects {

struct HeightCompression {
    float threshold = 0.5f;  // T
    float first_level = 0.5f, level_step = 0.1f;  // V0 = 0.5, 0.6, ...
    int steps = 0;  // the seed's 5: see above
    float k = 0.3f;
};

class DropHeightMap {
public:
    DropHeightMap(int width, int height);

    // Splats the metaballs over a glass of glass_size_m (radii times radius_scale),
    // then takes heights (compressed if asked) and normals. Leaves the GL viewport and framebuffer changed.
    void update(std::span<const RainMetaball> metaballs, glm::vec2 glass_size_m, float radius_scale,
                const HeightCompression& compression = {});

    // rg: the normal's u and v components (z is implied), b: height in mm, a: 1 on water.
    const gl::Texture& surface() const { return surface_; }
    // The last update's tiles: `wet` says where the surface can hold water.
    const DropTiles& tiles() const { return tiles_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_, height_;
    gl::Texture surface_;
    gl::Texture sums_;     // sums over drops of N, N^2 R (mm), N^2 x^2, N^2
    gl::Texture heights_;  // R32F mm: the normals pass gathers a texel and its neighbours at once
    gl::Framebuffer sums_fbo_, heights_fbo_, surface_fbo_;
    gl::Texture wet_depth_;  // the wet tiles marked, for the splats' depth test
    gl::Program splat_, shape_, normals_, mark_;
    gl::VertexArray vao_;
    gl::Buffer instances_;
    DropTiles tiles_;
    WetTiles wet_;
};

}  // namespace effects
