#include "effects/scene/GpuModel.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "effects/gl/DrawCount.h"

namespace effects {

GpuModel::GpuModel(const Model& model) : name_(model.name) {
    std::vector<MeshVertex> verts;
    std::vector<uint32_t> idx;
    for (const MeshData& m : model.meshes) {
        uint32_t base = uint32_t(verts.size());
        glm::vec3 lo(0.0f), hi(0.0f);
        if (!m.vertices.empty()) lo = hi = m.vertices.front().position;
        for (const MeshVertex& v : m.vertices) {
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
        }
        ranges_.push_back({GLsizei(m.indices.size()), idx.size(), m.roughness, m.metallic, m.emissive, m.name, 0.5f * (lo + hi), lo, hi});
        verts.insert(verts.end(), m.vertices.begin(), m.vertices.end());
        for (uint32_t i : m.indices) idx.push_back(base + i);
    }
    vertices_ = gl::Buffer::create<MeshVertex>("model." + model.name + ".vertices", verts, 0);
    indices_ = gl::Buffer::create<uint32_t>("model." + model.name + ".indices", idx, 0);
    vao_ = mesh_vertex_array("model." + model.name, vertices_, indices_);
}

gl::VertexArray mesh_vertex_array(std::string_view label, const gl::Buffer& vertices, const gl::Buffer& indices) {
    gl::VertexArray vao = gl::VertexArray::create(label);
    vao.attribute(0, 0, 3, GL_FLOAT, offsetof(MeshVertex, position));
    vao.attribute(1, 0, 3, GL_FLOAT, offsetof(MeshVertex, normal));
    vao.attribute(2, 0, 4, GL_FLOAT, offsetof(MeshVertex, color));
    vao.vertex_buffer(0, vertices, 0, sizeof(MeshVertex));
    vao.element_buffer(indices);
    return vao;
}

void GpuModel::draw(const gl::Program& program, bool depth_only) const {
    vao_.bind();
    for (const Range& r : ranges_) draw_range(program, depth_only, r);
}

void GpuModel::draw_range(const gl::Program& program, bool depth_only, const Range& r) const {
    if (!depth_only) {
        program.set("u_roughness", r.roughness);
        program.set("u_metallic", r.metallic);
        program.set("u_emissive", r.emissive);
    }
    gl::count_draw(r.index_count);
    glDrawElements(GL_TRIANGLES, r.index_count, GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(r.first_index * sizeof(uint32_t)));
}

glm::vec3 GpuModel::part_centre(std::string_view mesh) const {
    for (const Range& r : ranges_)
        if (r.name == mesh) return r.centre;
    return glm::vec3(0.0f);
}

std::vector<size_t> GpuModel::part_order(const std::optional<glm::vec3>& eye) const {
    std::vector<PartBox> boxes;
    boxes.reserve(ranges_.size());
    for (const Range& r : ranges_) boxes.push_back({r.lo, r.hi});
    if (!eye) {
        std::vector<size_t> order(boxes.size());
        std::iota(order.begin(), order.end(), size_t(0));
        return order;
    }
    return nearest_first(boxes, *eye);
}

std::vector<size_t> nearest_first(const std::vector<PartBox>& boxes, glm::vec3 eye) {
    std::vector<size_t> order(boxes.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::vector<float> key(boxes.size());
    for (size_t i = 0; i < boxes.size(); ++i) {
        const float d = glm::distance(eye, glm::clamp(eye, boxes[i].lo, boxes[i].hi));
        key[i] = d > 0.0f ? d : std::numeric_limits<float>::infinity();
    }
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return key[a] < key[b]; });
    return order;
}

Model make_sphere_model(int rings, int segments) {
    Model model;
    model.name = "sphere";
    MeshData m;
    m.name = "sphere";
    m.roughness = 0.6f;
    const float pi = 3.14159265f;
    for (int r = 0; r <= rings; ++r) {
        float theta = pi * float(r) / float(rings);
        for (int s = 0; s <= segments; ++s) {
            float phi = 2.0f * pi * float(s) / float(segments);
            glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            m.vertices.push_back({n, n, glm::vec4(1.0f)});
        }
    }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            uint32_t a = uint32_t(r * (segments + 1) + s), b = a + uint32_t(segments + 1);
            m.indices.insert(m.indices.end(), {a, a + 1, b, b, a + 1, b + 1});
        }
    model.meshes.push_back(std::move(m));
    model.bounds_min = glm::vec3(-1.0f);
    model.bounds_max = glm::vec3(1.0f);
    return model;
}

Model make_box_model() {
    Model model;
    model.name = "box";
    MeshData m;
    m.name = "box";
    m.roughness = 0.6f;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = 1.0f;
            if (sign < 0.0f) std::swap(u, v);  // counter-clockwise seen from outside
            const uint32_t first = uint32_t(m.vertices.size());
            for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
                m.vertices.push_back({n + c.x * u + c.y * v, n, glm::vec4(1.0f)});
            m.indices.insert(m.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
        }
    model.meshes.push_back(std::move(m));
    model.bounds_min = glm::vec3(-1.0f);
    model.bounds_max = glm::vec3(1.0f);
    return model;
}

}  // namespace effects
