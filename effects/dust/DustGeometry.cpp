#include "effects/dust/DustGeometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>

#include "effects/dust/SkyExposure.h"

namespace effects {

void DustGeometry::upload_static(const sim::DustField& field, const sim::DustDesc& dust, const SceneDesc& scene) {
    const sim::DustSurface& s = field.surface();
    std::vector<float> packed;
    packed.reserve(s.positions().size() * 6);
    for (size_t v = 0; v < s.positions().size(); ++v) {
        glm::vec3 p = s.positions()[v], n = s.normals()[v];
        packed.insert(packed.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
    }
    vertices_ = gl::Buffer::create<float>("dust.vertices", packed, 0);
    vertex_light_ = gl::Buffer::create("dust.vertex_light",
                                       GLsizeiptr(std::max<size_t>(s.positions().size(), 1) * 2 * sizeof(float) * 4));
    std::vector<float> sky = effects::sky_exposure(s, scene);
    if (sky.empty()) sky.push_back(1.0f);
    sky_exposure_ = gl::Buffer::create<float>("dust.sky_exposure", sky, 0);
    amounts_ = gl::Buffer::create("dust.amounts", GLsizeiptr(std::max<size_t>(s.positions().size(), 1) * sizeof(float)));
    shell_vao_ = gl::VertexArray::create("dust.shells");
    shell_vao_.attribute(0, 0, 3, GL_FLOAT, 0);
    shell_vao_.attribute(1, 0, 3, GL_FLOAT, 3 * sizeof(float));
    shell_vao_.attribute(2, 1, 1, GL_FLOAT, 0);
    shell_vao_.vertex_buffer(0, vertices_, 0, 6 * sizeof(float));
    shell_vao_.vertex_buffer(1, amounts_, 0, sizeof(float));
    fin_vao_ = gl::VertexArray::create("dust.fins");
    fin_vao_.attribute(0, 0, 3, GL_FLOAT, offsetof(FinVertex, position));
    fin_vao_.attribute(1, 0, 3, GL_FLOAT, offsetof(FinVertex, normal));
    fin_vao_.attribute(2, 0, 1, GL_FLOAT, offsetof(FinVertex, amount));
    fin_vao_.attribute(3, 0, 2, GL_FLOAT, offsetof(FinVertex, along_m));
    fin_vao_.attribute_integer(4, 0, 1, GL_UNSIGNED_INT, offsetof(FinVertex, vertex));
    coarsen(field, dust);
}

void DustGeometry::coarsen(const sim::DustField& field, const sim::DustDesc& dust) {
    const sim::DustSurface& fine = field.surface();
    const sim::DustSurface coarse(dust.props, 2.0f * dust.sample_spacing_m);
    // Bisection halves the same edges in the same order, so each coarse vertex is one
    // of the sim's, bit for bit: find it by position and normal within its prop.
    using Key = std::array<float, 6>;
    auto key = [](glm::vec3 p, glm::vec3 n) { return Key{p.x, p.y, p.z, n.x, n.y, n.z}; };
    if (coarse.props().size() != fine.props().size())
        throw std::logic_error("dust: the level's dusty props are not the field's");
    coarse_indices_.clear();
    coarse_props_.clear();
    for (size_t p = 0; p < fine.props().size(); ++p) {
        const sim::DustPropRange& f = fine.props()[p];
        const sim::DustPropRange& c = coarse.props()[p];
        std::map<Key, uint32_t> by_key;
        for (uint32_t v = f.first_vertex; v < f.first_vertex + f.vertex_count; ++v)
            by_key.emplace(key(fine.positions()[v], fine.normals()[v]), v);
        std::vector<uint32_t> to_fine(c.vertex_count);
        for (uint32_t v = 0; v < c.vertex_count; ++v) {
            const glm::vec3 pos = coarse.positions()[c.first_vertex + v], n = coarse.normals()[c.first_vertex + v];
            if (auto it = by_key.find(key(pos, n)); it != by_key.end()) {
                to_fine[v] = it->second;
                continue;
            }
            // Not found bit for bit (should not happen): the nearest of the sim's vertices.
            float best = INFINITY;
            for (uint32_t w = f.first_vertex; w < f.first_vertex + f.vertex_count; ++w) {
                float d = glm::length(fine.positions()[w] - pos) + glm::length(fine.normals()[w] - n);
                if (d < best) best = d, to_fine[v] = w;
            }
        }
        coarse_props_.emplace_back(uint32_t(coarse_indices_.size()), c.index_count);
        for (uint32_t i = c.first_index; i < c.first_index + c.index_count; ++i)
            coarse_indices_.push_back(to_fine[coarse.indices()[i] - c.first_vertex]);
    }
}

void DustGeometry::rebuild(const sim::DustField& field) {
    const sim::DustSurface& s = field.surface();
    std::span<const float> amount = field.amounts();
    amounts_.update<float>(0, amount);
    scratch_indices_.clear();
    scratch_fins_.clear();
    scratch_fin_indices_.clear();
    scratch_lit_.clear();
    for (int level = 0; level < kLevels; ++level) {
        const std::vector<uint32_t>& idx = level == 0 ? s.indices() : coarse_indices_;
        ranges_[size_t(level)].assign(s.props().size(), {});
        const size_t first_triangle = scratch_indices_.size() / 3, first_fin = scratch_fins_.size() / 4;
        for (size_t p = 0; p < s.props().size(); ++p) {
            const auto [first_index, index_count] =
                level == 0 ? std::pair{s.props()[p].first_index, s.props()[p].index_count} : coarse_props_[p];
            DustDrawRange& r = ranges_[size_t(level)][p];
            r.first_shell_index = scratch_indices_.size();
            r.first_fin_index = scratch_fin_indices_.size();
            std::map<std::pair<uint32_t, uint32_t>, int> edges;  // how many dusty triangles share it
            for (uint32_t t = first_index; t < first_index + index_count; t += 3) {
                uint32_t a = idx[t], b = idx[t + 1], c = idx[t + 2];
                if (std::max({amount[a], amount[b], amount[c]}) <= kMinAmount) continue;
                scratch_indices_.insert(scratch_indices_.end(), {a, b, c});
                for (auto [u, v] : {std::pair{a, b}, {b, c}, {c, a}}) ++edges[{std::min(u, v), std::max(u, v)}];
            }
            // A fin on every dusty edge: it stands up across the surface at grazing angles.
            for (const auto& [edge, count] : edges) {
                (void)count;
                auto [u, v] = edge;
                glm::vec3 pu = s.positions()[u], pv = s.positions()[v];
                float len = glm::length(pv - pu);
                auto base = uint32_t(scratch_fins_.size());
                for (int k = 0; k < 4; ++k) {
                    uint32_t w = (k == 0 || k == 3) ? u : v;
                    glm::vec3 p = s.positions()[w], n = s.normals()[w];
                    // Along-edge coordinate offset by where the edge lies, so fins differ.
                    float along = (w == u ? 0.0f : len) + glm::dot(pu, glm::vec3(0.37f, 0.11f, 0.61f));
                    scratch_fins_.push_back({{p.x, p.y, p.z}, {n.x, n.y, n.z}, amount[w], along, k < 2 ? 0.0f : 1.0f, w});
                }
                scratch_fin_indices_.insert(scratch_fin_indices_.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
            }
            // Only the vertices under dust are lit each frame: the rest draw nothing.
            r.first_lit = uint32_t(scratch_lit_.size());
            std::vector<uint32_t> lit(scratch_indices_.begin() + std::ptrdiff_t(r.first_shell_index), scratch_indices_.end());
            std::sort(lit.begin(), lit.end());
            lit.erase(std::unique(lit.begin(), lit.end()), lit.end());
            scratch_lit_.insert(scratch_lit_.end(), lit.begin(), lit.end());
            r.lit_count = uint32_t(lit.size());
            r.shell_index_count = GLsizei(scratch_indices_.size() - r.first_shell_index);
            r.fin_index_count = GLsizei(scratch_fin_indices_.size() - r.first_fin_index);
        }
        dusty_triangles_[size_t(level)] = scratch_indices_.size() / 3 - first_triangle;
        fin_quads_[size_t(level)] = scratch_fins_.size() / 4 - first_fin;
    }
    // Storage sized for the first (fullest) build; clearing only ever shrinks the lists.
    auto fit = [](gl::Buffer& buffer, const char* label, size_t bytes) {
        if (buffer.id() == 0 || size_t(buffer.size()) < bytes)
            buffer = gl::Buffer::create(label, GLsizeiptr(std::max<size_t>(bytes, 16)));
    };
    fit(shell_indices_, "dust.shell_indices", scratch_indices_.size() * sizeof(uint32_t));
    fit(fin_vertices_, "dust.fin_vertices", scratch_fins_.size() * sizeof(FinVertex));
    fit(fin_indices_, "dust.fin_indices", scratch_fin_indices_.size() * sizeof(uint32_t));
    fit(lit_vertices_, "dust.lit_vertices", scratch_lit_.size() * sizeof(uint32_t));
    if (!scratch_indices_.empty()) shell_indices_.update<uint32_t>(0, scratch_indices_);
    if (!scratch_fins_.empty()) fin_vertices_.update<FinVertex>(0, scratch_fins_);
    if (!scratch_fin_indices_.empty()) fin_indices_.update<uint32_t>(0, scratch_fin_indices_);
    if (!scratch_lit_.empty()) lit_vertices_.update<uint32_t>(0, scratch_lit_);
    shell_vao_.element_buffer(shell_indices_);
    fin_vao_.vertex_buffer(0, fin_vertices_, 0, sizeof(FinVertex));
    fin_vao_.element_buffer(fin_indices_);
}

void DustGeometry::update(const sim::DustField& field, uint64_t restore_generation, const sim::DustDesc& dust,
                          const SceneDesc& scene) {
    if (&field != field_) {
        field_ = &field;
        upload_static(field, dust, scene);
        revision_ = ~0ull;
    }
    if (restore_generation != restore_generation_) {
        restore_generation_ = restore_generation;
        revision_ = ~0ull;
    }
    if (field.revision() != revision_) {
        revision_ = field.revision();
        rebuild(field);
    }
}

}  // namespace effects
