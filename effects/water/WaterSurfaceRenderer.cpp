#include "effects/water/WaterSurfaceRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "effects/gl/DrawCount.h"

namespace effects {

WaterSurfaceRenderer::WaterSurfaceRenderer()
    : program_(gl::Program::from_files("water.surface", {"water/surface.vert.glsl", "water/surface.frag.glsl"})) {}

void WaterSurfaceRenderer::rebuild(const WaterView& view, const Shape& shape) {
    mesh_ = make_water_surface_mesh(view.grid ? &*view.grid : nullptr, kMaxLatticeCells, kTileCells, kHorizonExtent_m);
    vertices_ = gl::Buffer::create<SurfaceVertex>("water.surface.vertices", mesh_.vertices, 0);
    indices_ = gl::Buffer::create<uint32_t>("water.surface.indices", mesh_.indices, 0);
    mesh_.vertices = {};
    mesh_.indices = {};
    vao_ = gl::VertexArray::create("water.surface");
    vao_.attribute(0, 0, 4, GL_FLOAT, 0);
    vao_.vertex_buffer(0, vertices_, 0, sizeof(SurfaceVertex));
    vao_.element_buffer(indices_);

    // Without a grid the shaders still sample a (zero) grid: a 1x1 texture.
    const int side = shape.has_grid ? shape.size : 1;
    grid_texture_ = gl::Texture::create_2d("water.grid", GL_RGBA32F, side, side, gl::Texture::full_mip_levels(side, side));
    grid_texture_.set_filter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    grid_texture_.set_wrap(GL_CLAMP_TO_EDGE);
    if (!shape.has_grid) {
        const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        grid_texture_.upload<float>(GL_RGBA, GL_FLOAT, std::span<const float>(zero, 4));
    }
    shape_ = shape;
}

void WaterSurfaceRenderer::update(const WaterView& view) {
    Shape shape;
    if (view.grid) shape = {true, view.grid->size, view.grid->spacing_m, view.grid->origin_xz};
    if (shape_ != shape) rebuild(view, shape);
    sea_level_m_ = view.sea_level_m;
    min_height_ = max_height_ = 0.0f;
    if (view.grid) {
        for (float h : view.grid->heights)
            if (std::isfinite(h)) {
                min_height_ = std::min(min_height_, h);
                max_height_ = std::max(max_height_, h);
            }
        grid_mips_.derive(*view.grid);
        for (int level = 0; level < grid_mips_.levels(); ++level)
            grid_texture_.upload<glm::vec4>(GL_RGBA, GL_FLOAT, grid_mips_.level(level), level);
    }

    const gl::Program& p = program_;
    const LatticeLayout& l = mesh_.lattice;
    set_grid(p);
    p.set("u_lattice_origin", l.origin_xz);
    p.set("u_lattice_cell_m", l.cell_m);
    p.set("u_lattice_cells", l.lattice_cells);
}

void WaterSurfaceRenderer::set_grid(const gl::Program& p) const {
    const Shape shape = shape_.value_or(Shape{});
    p.set("u_has_grid", shape.has_grid ? 1 : 0);
    p.set("u_grid_size", shape.has_grid ? shape.size : 1);
    p.set("u_grid_spacing", shape.has_grid ? shape.spacing_m : 1.0f);
    p.set("u_grid_origin", shape.origin_xz);
    p.set("u_wave_grid", int(kGridUnit));
}

void WaterSurfaceRenderer::bind_grid_textures() const {
    grid_texture_.bind(kGridUnit);
}

void WaterSurfaceRenderer::bounds(glm::vec3& lo, glm::vec3& hi) const {
    const float e = mesh_.half_extent_m;
    lo = glm::vec3(-e, sea_level_m_ + min_height_ - 0.01f, -e);
    hi = glm::vec3(e, sea_level_m_ + max_height_ + 0.01f, e);
}

void WaterSurfaceRenderer::draw(const Camera& camera, int viewport_height, float target_cell_px) {
    const gl::Program& p = program_;
    bind_grid_textures();
    vao_.bind();
    auto draw_range = [](const IndexRange& r) {
        gl::count_draw(int64_t(r.count));
        glDrawElements(GL_TRIANGLES, GLsizei(r.count), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(size_t(r.first) * sizeof(uint32_t)));
    };
    const LatticeLayout& l = mesh_.lattice;
    tiles_.clear();
    if (l.lattice_cells > 0) {
        LodView lod;
        lod.view_proj = camera.view_proj;
        lod.eye = camera.eye;
        lod.pixels_per_radian = 0.5f * camera.proj[1][1] * float(viewport_height);
        lod.target_cell_px = target_cell_px;
        lod.min_y = sea_level_m_ + min_height_ - 0.01f;
        lod.max_y = sea_level_m_ + max_height_ + 0.01f;
        tiles_ = plan_tiles(l, lod);
        p.set("u_tile_cells", l.tile_cells);
        for (const TileDraw& t : tiles_) {
            p.set("u_tile_origin", t.tile * l.tile_cells);
            glProgramUniform4i(p.id(), p.location("u_edge_stride"), t.edge_stride.x, t.edge_stride.y, t.edge_stride.z,
                               t.edge_stride.w);
            int level = 0;
            while ((1 << level) < t.stride) ++level;
            draw_range(mesh_.tile_strides[size_t(level)]);
        }
    }
    // The frame's lattice vertices are absolute: no tile offset, no folding.
    p.set("u_tile_origin", glm::ivec2(0));
    p.set("u_tile_cells", 1 << 30);
    glProgramUniform4i(p.id(), p.location("u_edge_stride"), 1, 1, 1, 1);
    draw_range(mesh_.frame);
}

}  // namespace effects
