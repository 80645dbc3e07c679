#include "effects/rain/WetTiles.h"

#include <glm/vec2.hpp>

#include "effects/gl/EmptyVertexArray.h"

namespace effects {

namespace {
constexpr GLuint kRunsBinding = 3;  // shaders/rain/tiles.vert.glsl
}  // namespace

void WetTiles::set(const DropTiles& tiles, int width, int height) {
    gl::upload_growing(runs_, "rain.wet_tiles", std::as_bytes(std::span(tiles.wet)));
    cols_ = tiles.cols;
    width_ = width;
    height_ = height;
    runs_count_ = tiles.wet.size();
}

void WetTiles::draw(const gl::Program& program) const {
    const float zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    cover(program);
}

void WetTiles::cover(const gl::Program& program) const {
    if (runs_count_ == 0) return;
    program.set("u_tile_texels", DropTiles::kTexels);
    program.set("u_tile_cols", cols_);
    program.set("u_texels", glm::vec2(float(width_), float(height_)));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRunsBinding, runs_.id());
    gl::bind_empty_vertex_array();
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(6 * runs_count_));
}

}  // namespace effects
