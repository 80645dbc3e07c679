#pragma once
// Draws the sea surface's geometry step (WaterShading): the wave grid's lattice tiles
// (strides from SurfaceLod), displaced by the grid's heights, and the flat frame
// around them (shaders/water/surface.*.glsl), depth only. Each frame the grid's heights,
// slopes and curvature (WaveGridMips) go into one mipmapped RGBA32F texture, which the
// vertices and the sea's shading read.
#include <optional>
#include <vector>

#include "effects/gl/Buffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/gl/VertexArray.h"
#include "effects/scene/Camera.h"
#include "effects/water/SurfaceLod.h"
#include "effects/water/WaveGridMips.h"
#include "effects/water/WaterSurfaceMesh.h"
#include "effects/water/WaterView.h"

namespace effects {

class WaterSurfaceRenderer {
public:
    static constexpr int kMaxLatticeCells = 256;
    static constexpr int kTileCells = 32;
    static constexpr float kHorizonExtent_m = 3000.0f;  // the flat frame's reach
    static constexpr GLuint kGridUnit = 2;

    WaterSurfaceRenderer();

    // Derives the grid's texels and uploads them. Rebuilds the mesh when the grid's
    // shape changed.
    void update(const WaterView& view);
    // Draws into the bound framebuffer with the program's shared uniforms already set.
    void draw(const Camera& camera, int viewport_height, float target_cell_px);
    // For another program that reads the grid (the sea's shading): sets its u_has_grid,
    // u_grid_{size,spacing,origin} and u_wave_grid as of the last update(), and binds
    // that texture to its unit.
    void set_grid(const gl::Program& program) const;
    void bind_grid_textures() const;

    const gl::Program& program() const { return program_; }
    const std::vector<TileDraw>& last_tiles() const { return tiles_; }
    const LatticeLayout& lattice() const { return mesh_.lattice; }
    // A box holding everything draw() draws, as of the last update().
    void bounds(glm::vec3& lo, glm::vec3& hi) const;

private:
    struct Shape {
        bool has_grid = false;
        int size = 0;
        float spacing_m = 0.0f;
        glm::vec2 origin_xz{0.0f};
        bool operator==(const Shape&) const = default;
    };
    void rebuild(const WaterView& view, const Shape& shape);

    gl::Program program_;
    WaveGridMips grid_mips_;
    gl::Texture grid_texture_;
    gl::Buffer vertices_, indices_;
    gl::VertexArray vao_;
    WaterSurfaceMesh mesh_;  // indices dropped after upload; ranges and layout kept
    std::optional<Shape> shape_;
    float sea_level_m_ = 0.0f, min_height_ = 0.0f, max_height_ = 0.0f;  // for culling
    std::vector<TileDraw> tiles_;
};

}  // namespace effects
