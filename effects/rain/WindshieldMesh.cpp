#include "effects/rain/WindshieldMesh.h"

#include <algorithm>
#include <vector>

#include <glm/geometric.hpp>

#include "sim/rain/GlassSurface.h"

namespace effects {

namespace {
struct Vertex {
    glm::vec3 position;
    glm::vec2 uv_m;
    glm::vec3 tangent_u, tangent_v;
};
}  // namespace

WindshieldMesh::WindshieldMesh(const sim::GlassSurface& glass, int columns, int rows)
    : glass_(&glass), grid_{columns, rows, glm::vec2(glass.width_m(), glass.height_m())},
      vao_(gl::VertexArray::create("rain.windshield")) {
    const glm::vec2 size = grid_.glass_size_m;
    const float e = 1e-3f;
    std::vector<Vertex> verts;
    for (int j = 0; j <= rows; ++j)
        for (int i = 0; i <= columns; ++i) {
            glm::vec2 uv = size * glm::vec2(float(i) / float(columns), float(j) / float(rows));
            Vertex v;
            v.position = glass.point(uv);
            v.uv_m = uv;
            v.tangent_u = glm::normalize(glass.point(uv + glm::vec2(e, 0.0f)) - glass.point(uv - glm::vec2(e, 0.0f)));
            v.tangent_v = glm::normalize(glass.point(uv + glm::vec2(0.0f, e)) - glass.point(uv - glm::vec2(0.0f, e)));
            verts.push_back(v);
        }
    std::vector<uint32_t> idx;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            uint32_t a = uint32_t(j * (columns + 1) + i), b = a + 1, c = a + uint32_t(columns + 1), d = c + 1;
            idx.insert(idx.end(), {a, b, d, a, d, c});
        }
    vertices_ = gl::Buffer::create<Vertex>("rain.windshield.vertices", verts, 0);
    indices_ = gl::Buffer::create<uint32_t>("rain.windshield.indices", idx, 0);
    vao_.attribute(0, 0, 3, GL_FLOAT, offsetof(Vertex, position));
    vao_.attribute(1, 0, 2, GL_FLOAT, offsetof(Vertex, uv_m));
    vao_.attribute(2, 0, 3, GL_FLOAT, offsetof(Vertex, tangent_u));
    vao_.attribute(3, 0, 3, GL_FLOAT, offsetof(Vertex, tangent_v));
    vao_.vertex_buffer(0, vertices_, 0, sizeof(Vertex));
    vao_.element_buffer(indices_);
}

void WindshieldMesh::draw(std::span<const uint8_t> shown) {
    run_counts_.clear();
    run_offsets_.clear();
    const size_t cells = std::min(shown.size(), size_t(grid_.columns) * size_t(grid_.rows));
    for (size_t c = 0; c < cells; ++c) {
        if (!shown[c]) continue;
        const bool continues = c % size_t(grid_.columns) != 0 && shown[c - 1];
        if (continues) run_counts_.back() += 6;
        else {
            run_counts_.push_back(6);
            run_offsets_.push_back(reinterpret_cast<const void*>(c * 6 * sizeof(uint32_t)));
        }
    }
    if (run_counts_.empty()) return;
    vao_.bind();
    glMultiDrawElements(GL_TRIANGLES, run_counts_.data(), GL_UNSIGNED_INT, run_offsets_.data(), GLsizei(run_counts_.size()));
}

}  // namespace effects
