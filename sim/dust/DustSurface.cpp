#include "sim/dust/DustSurface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace sim {

namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Vertices of neighbouring triangles land on the same point up to rounding: merge
// them on a 0.1 mm grid (and normals on a 1e-3 grid). The map is only looked up,
// never iterated: vertex numbers follow first use, whatever the hash.
using VertexKey = std::array<int32_t, 6>;
struct VertexKeyHash {
    size_t operator()(const VertexKey& k) const {
        uint64_t h = 0x9e3779b97f4a7c15ull;
        for (int32_t v : k) h = (h ^ uint32_t(v)) * 0x100000001b3ull;
        return size_t(h ^ (h >> 29));
    }
};
VertexKey key_of(glm::vec3 p, glm::vec3 n) {
    auto q = [](float v, float step) { return int32_t(std::lround(v / step)); };
    return {q(p.x, 1e-4f), q(p.y, 1e-4f), q(p.z, 1e-4f), q(n.x, 1e-3f), q(n.y, 1e-3f), q(n.z, 1e-3f)};
}

struct Piece {  // a triangle on the bisection stack, in the original winding
    glm::vec3 p[3], n[3];
    int depth;
};
constexpr int kMaxDepth = 2 * DustSurface::kMaxSplits;

}  // namespace

float DustPropRange::radius() const { return 0.5f * glm::length(bounds.max - bounds.min); }

DustSurface::DustSurface(const std::vector<DustyPropDesc>& props, float spacing_m) {
    if (!(spacing_m > 0.0f) || !std::isfinite(spacing_m))
        throw std::invalid_argument("dust: sample spacing must be positive and finite");
    for (const DustyPropDesc& prop : props) {
        const std::string who = "dust: prop " + prop.name;
        if (prop.positions.size() != prop.normals.size())
            throw std::invalid_argument(who + " has " + std::to_string(prop.positions.size()) + " positions but " +
                                        std::to_string(prop.normals.size()) + " normals");
        if (prop.indices.empty() || prop.indices.size() % 3 != 0)
            throw std::invalid_argument(who + " has no triangles (or an index count not a multiple of 3)");
        DustPropRange range;
        range.name = prop.name;
        range.kind = prop.kind;
        range.first_vertex = uint32_t(positions_.size());
        range.first_index = uint32_t(indices_.size());
        std::unordered_map<VertexKey, uint32_t, VertexKeyHash> merged;
        auto vertex = [&](glm::vec3 p, glm::vec3 n) {
            auto [it, added] = merged.try_emplace(key_of(p, n), uint32_t(positions_.size()));
            if (added) {
                positions_.push_back(p);
                normals_.push_back(n);
                if (positions_.size() > kMaxVertices)
                    throw std::invalid_argument(who + ": the dusty props need more than " +
                                                std::to_string(kMaxVertices) +
                                                " vertices at this sample spacing; raise sample_spacing_m");
            }
            return it->second;
        };
        std::vector<Piece> stack;
        for (size_t t = 0; t < prop.indices.size(); t += 3) {
            uint32_t ia = prop.indices[t], ib = prop.indices[t + 1], ic = prop.indices[t + 2];
            if (std::max({ia, ib, ic}) >= prop.positions.size())
                throw std::invalid_argument(who + ": triangle " + std::to_string(t / 3) + " indexes past its vertices");
            glm::vec3 a = prop.positions[ia], b = prop.positions[ib], c = prop.positions[ic];
            glm::vec3 na = prop.normals[ia], nb = prop.normals[ib], nc = prop.normals[ic];
            if (!finite(a) || !finite(b) || !finite(c) || !finite(na) || !finite(nb) || !finite(nc))
                throw std::invalid_argument(who + ": triangle " + std::to_string(t / 3) + " is not finite");
            if (glm::length(glm::cross(b - a, c - a)) < 1e-10f) continue;  // degenerate: nothing to hold dust
            // Longest-edge bisection until every edge is at most spacing_m: thin
            // triangles (planks, battens) split only across their length.
            stack.clear();
            stack.push_back({a, b, c, na, nb, nc, 0});
            while (!stack.empty()) {
                Piece t = stack.back();
                stack.pop_back();
                float e[3] = {glm::length(t.p[1] - t.p[0]), glm::length(t.p[2] - t.p[1]), glm::length(t.p[0] - t.p[2])};
                int k = e[0] >= e[1] && e[0] >= e[2] ? 0 : (e[1] >= e[2] ? 1 : 2);
                if (e[k] <= spacing_m || t.depth >= kMaxDepth) {
                    for (int i = 0; i < 3; ++i) indices_.push_back(vertex(t.p[i], t.n[i]));
                    continue;
                }
                int k1 = (k + 1) % 3;
                glm::vec3 mp = (t.p[k] + t.p[k1]) * 0.5f, mn = t.n[k] + t.n[k1];
                float len = glm::length(mn);
                mn = len > 1e-8f ? mn / len : t.n[k];
                Piece first = t, second = t;
                first.p[k1] = mp, first.n[k1] = mn;   // k, mid, k2
                second.p[k] = mp, second.n[k] = mn;   // mid, k1, k2
                first.depth = second.depth = t.depth + 1;
                stack.push_back(second);
                stack.push_back(first);
            }
        }
        range.vertex_count = uint32_t(positions_.size()) - range.first_vertex;
        range.index_count = uint32_t(indices_.size()) - range.first_index;
        if (range.vertex_count == 0) throw std::invalid_argument(who + " has only degenerate triangles");
        range.bounds.min = range.bounds.max = positions_[range.first_vertex];
        for (uint32_t v = range.first_vertex; v < range.first_vertex + range.vertex_count; ++v) {
            range.bounds.min = glm::min(range.bounds.min, positions_[v]);
            range.bounds.max = glm::max(range.bounds.max, positions_[v]);
        }
        props_.push_back(std::move(range));
    }
}

}  // namespace sim
