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
// Per frame only the splat: clear and splat the sums (instanced quads, additive
// RGBA16F, depth-tested against the wet tiles marked in a depth buffer: 5-7% off the
// splat). The windshield takes the height and the normal per pixel from the sums read
// bilinearly at the pixel and one texel along u and v (shaders/rain/drop_shape.glsl):
// the density field is smooth where the height is not, so a map coarser than the
// pixels still gives round, sharp outlines and smooth normals, and no per-texel pass
// runs in the frame. surface() takes the same function per texel (at the texel
// centres, where the filtered sums are the texel's own) for the tests and the bench,
// over the wet tiles (drops_by_tile's `wet` runs, WetTiles) and cleared elsewhere.
// Before, the frame ran a height pass and a normals pass over the wet tiles and the
// windshield filtered their results (docs/effects/rain.md, "Benchmarks").
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

    // Splats the metaballs over a glass of glass_size_m (radii times radius_scale); their
    // heights are taken with `compression`. Leaves the GL viewport and framebuffer changed.
    void update(std::span<const RainMetaball> metaballs, glm::vec2 glass_size_m, float radius_scale,
                const HeightCompression& compression = {});

    // The sums over drops of N, N^2 R (mm), N^2 x^2, N^2; linear filtering.
    const gl::Texture& sums() const { return sums_; }
    // Sets drop_shape.glsl's uniforms on `program` (the threshold and the compression)
    // and u_texel_mm, one texel of the map in glass millimetres, for the last update.
    void set_shape(const gl::Program& program) const;
    // The surface per texel as the windshield takes it (rg: the normal's u and v
    // components, z implied; b: height in mm; a: 1 on water), made from the last update
    // on the first call after it. Leaves the GL viewport and framebuffer changed.
    const gl::Texture& surface();
    // The last update's tiles: `wet` says where the surface can hold water.
    const DropTiles& tiles() const { return tiles_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_, height_;
    gl::Texture surface_;
    gl::Texture sums_;     // sums over drops of N, N^2 R (mm), N^2 x^2, N^2
    gl::Framebuffer sums_fbo_, surface_fbo_;
    gl::Texture wet_depth_;  // the wet tiles marked, for the splats' depth test
    gl::Program splat_, shape_, mark_;
    gl::VertexArray vao_;
    gl::Buffer instances_;
    DropTiles tiles_;
    WetTiles wet_;
    glm::vec2 glass_size_m_{1.0f};
    HeightCompression compression_;
    bool surface_made_ = false;  // surface_ holds the last update's
};

}  // namespace effects
