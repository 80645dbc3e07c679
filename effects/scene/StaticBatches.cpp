#include "effects/scene/StaticBatches.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <tuple>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "effects/gl/DrawCount.h"
#include "effects/scene/GpuModel.h"

namespace effects {

namespace {

// Orders batches' keys: the material's values exactly (meshes share them when their
// glTF material is the same), then the square.
using Key = std::tuple<float, float, float, float, float, int, int>;

}  // namespace

StaticBatches::StaticBatches(const SceneDesc& desc, float cell_m) {
    struct Pending {
        Batch batch;
        std::vector<MeshVertex> vertices;
        std::vector<uint32_t> indices;
        bool empty = true;
    };
    std::map<Key, Pending> pending;
    for (const PropInstance& inst : desc.props) {
        const Model& model = desc.models[size_t(inst.model)];
        // As mesh.vert.glsl would place them with u_model and u_normal_matrix: the
        // normal is left unnormalised (the shader normalises it).
        const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(inst.transform)));
        for (const MeshData& mesh : model.meshes) {
            if (mesh.indices.empty()) continue;
            glm::vec3 lo(0.0f), hi(0.0f);
            std::vector<MeshVertex> placed;
            placed.reserve(mesh.vertices.size());
            for (const MeshVertex& v : mesh.vertices) {
                MeshVertex w = v;
                w.position = glm::vec3(inst.transform * glm::vec4(v.position, 1.0f));
                w.normal = normal_matrix * v.normal;
                lo = placed.empty() ? w.position : glm::min(lo, w.position);
                hi = placed.empty() ? w.position : glm::max(hi, w.position);
                placed.push_back(w);
            }
            const glm::vec3 centre = 0.5f * (lo + hi);
            const Key key{mesh.roughness, mesh.metallic, mesh.emissive.x, mesh.emissive.y, mesh.emissive.z,
                          int(std::floor(centre.x / cell_m)), int(std::floor(centre.z / cell_m))};
            Pending& p = pending[key];
            if (p.empty) {
                p.batch = {.roughness = mesh.roughness, .metallic = mesh.metallic, .emissive = mesh.emissive, .lo = lo, .hi = hi};
                p.empty = false;
            }
            p.batch.lo = glm::min(p.batch.lo, lo);
            p.batch.hi = glm::max(p.batch.hi, hi);
            const uint32_t base = uint32_t(p.vertices.size());
            p.vertices.insert(p.vertices.end(), placed.begin(), placed.end());
            for (uint32_t i : mesh.indices) p.indices.push_back(base + i);
        }
    }
    std::vector<MeshVertex> vertices;
    std::vector<uint32_t> indices;
    for (auto& [key, p] : pending) {
        p.batch.first_index = indices.size();
        p.batch.index_count = GLsizei(p.indices.size());
        const uint32_t base = uint32_t(vertices.size());
        vertices.insert(vertices.end(), p.vertices.begin(), p.vertices.end());
        for (uint32_t i : p.indices) indices.push_back(base + i);
        batches_.push_back(p.batch);
    }
    if (batches_.empty()) return;
    vertices_ = gl::Buffer::create<MeshVertex>("props.batched.vertices", vertices, 0);
    indices_ = gl::Buffer::create<uint32_t>("props.batched.indices", indices, 0);
    vao_ = mesh_vertex_array("props.batched", vertices_, indices_);
}

void StaticBatches::draw(const gl::Program& p, bool depth_only, const Frustum& view,
                         const std::function<bool(glm::vec3, glm::vec3)>& select,
                         const std::optional<glm::vec3>& eye) const {
    if (batches_.empty()) return;
    std::vector<std::pair<float, const Batch*>> seen;
    for (const Batch& b : batches_)
        if (!view.outside(b.lo, b.hi) && (!select || select(b.lo, b.hi)))
            seen.emplace_back(eye ? glm::distance(*eye, glm::clamp(*eye, b.lo, b.hi)) : 0.0f, &b);
    if (eye)
        std::stable_sort(seen.begin(), seen.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    p.set("u_model", glm::mat4(1.0f));
    if (!depth_only) p.set("u_normal_matrix", glm::mat3(1.0f));
    vao_.bind();
    for (const auto& [distance, b] : seen) {
        if (!depth_only) {
            p.set("u_roughness", b->roughness);
            p.set("u_metallic", b->metallic);
            p.set("u_emissive", b->emissive);
        }
        gl::count_draw(b->index_count);
        glDrawElements(GL_TRIANGLES, b->index_count, GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(b->first_index * sizeof(uint32_t)));
    }
}

}  // namespace effects
