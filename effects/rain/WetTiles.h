#pragma once
// Draws a height map's per-texel passes over the tiles where water can be
// (DropTiles::wet) instead of over every texel: each run of wet tiles along a row is
// one rectangle (shaders/rain/tiles.vert.glsl), and the rest of the target is cleared
// to zero, which is what those passes write on dry glass.
#include "effects/gl/Buffer.h"
#include "effects/gl/Program.h"
#include "effects/rain/DropTiles.h"

namespace effects {

class WetTiles {
public:
    // Uploads the runs of `tiles`, over a width x height target.
    void set(const DropTiles& tiles, int width, int height);
    // Clears the bound framebuffer's colour 0 and draws `program` over the wet tiles.
    void draw(const gl::Program& program) const;
    // Draws `program` over the wet tiles, clearing nothing.
    void cover(const gl::Program& program) const;

private:
    gl::Buffer runs_;
    int cols_ = 0, width_ = 0, height_ = 0;
    size_t runs_count_ = 0;
};

}  // namespace effects
