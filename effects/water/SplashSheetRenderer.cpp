#include "effects/water/SplashSheetRenderer.h"

#include <cstddef>

namespace effects {

namespace {
// Grows a dynamic buffer to hold `bytes`, doubling so a growing splash reallocates rarely.
bool ensure_capacity(gl::Buffer& buffer, const char* label, size_t bytes) {
    if (buffer.id() != 0 && size_t(buffer.size()) >= bytes) return false;
    size_t capacity = buffer.id() != 0 ? size_t(buffer.size()) : 4096;
    while (capacity < bytes) capacity *= 2;
    buffer = gl::Buffer::create(label, GLsizeiptr(capacity));
    return true;
}
}  // namespace

SplashSheetRenderer::SplashSheetRenderer()
    : program_(gl::Program::from_files("water.sheet", {"water/sheet.vert.glsl", "water/sheet.frag.glsl"})),
      vao_(gl::VertexArray::create("water.sheet")) {
    vao_.attribute(0, 0, 3, GL_FLOAT, offsetof(SheetVertex, position));
    vao_.attribute(1, 0, 3, GL_FLOAT, offsetof(SheetVertex, normal));
    vao_.attribute(2, 0, 2, GL_FLOAT, offsetof(SheetVertex, cell));
    vao_.attribute(3, 0, 1, GL_FLOAT, offsetof(SheetVertex, stretch));
    vao_.attribute(4, 0, 1, GL_FLOAT, offsetof(SheetVertex, cover));
}

bool SplashSheetRenderer::update(const WaterView& view, float tear_stretch) {
    mesh_.clear();
    for (const SheetView& s : view.sheets) mesh_.append(s, tear_stretch, view.sea_level_m);
    if (mesh_.indices.empty()) return false;
    if (ensure_capacity(vertices_, "water.sheet.vertices", mesh_.vertices.size() * sizeof(SheetVertex)))
        vao_.vertex_buffer(0, vertices_, 0, sizeof(SheetVertex));
    if (ensure_capacity(indices_, "water.sheet.indices", mesh_.indices.size() * sizeof(uint32_t)))
        vao_.element_buffer(indices_);
    vertices_.update<SheetVertex>(0, mesh_.vertices);
    indices_.update<uint32_t>(0, mesh_.indices);
    return true;
}

void SplashSheetRenderer::draw() const {
    if (mesh_.indices.empty()) return;
    vao_.bind();
    glDrawElements(GL_TRIANGLES, GLsizei(mesh_.indices.size()), GL_UNSIGNED_INT, nullptr);
}

}  // namespace effects
