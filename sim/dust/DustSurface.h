#pragma once
// The dusty props' surfaces, finely tessellated so that a dust amount per vertex can
// show a cleared patch: the prop-local parameterisation the amounts live on. Built
// once from the level's triangles; the renderer draws the same vertices.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/dust/DustDesc.h"
#include "sim/world/LevelDesc.h"

namespace sim {

struct DustPropRange {
    std::string name;
    DustKind kind = DustKind::Dust;
    uint32_t first_vertex = 0, vertex_count = 0;
    uint32_t first_index = 0, index_count = 0;  // into DustSurface::indices (absolute vertex numbers)
    Aabb bounds;                                // of the prop's vertices
    glm::vec3 centre() const { return (bounds.min + bounds.max) * 0.5f; }
    float radius() const;                       // half the bounds' diagonal
};

class DustSurface {
public:
    DustSurface() = default;
    // Splits every triangle of every prop so that no edge is longer than spacing_m
    // (at most kMaxSplits per edge) and merges vertices that coincide in position and
    // normal. Throws std::invalid_argument naming the prop for malformed geometry.
    DustSurface(const std::vector<DustyPropDesc>& props, float spacing_m);

    static constexpr int kMaxSplits = 64;
    static constexpr size_t kMaxVertices = size_t(1) << 21;

    const std::vector<glm::vec3>& positions() const { return positions_; }
    const std::vector<glm::vec3>& normals() const { return normals_; }
    const std::vector<uint32_t>& indices() const { return indices_; }
    const std::vector<DustPropRange>& props() const { return props_; }

private:
    std::vector<glm::vec3> positions_, normals_;
    std::vector<uint32_t> indices_;
    std::vector<DustPropRange> props_;
};

}  // namespace sim
