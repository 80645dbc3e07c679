#include "effects/water/SplashSheetMesh.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace effects {

void SplashSheetMesh::append(const SheetView& sheet, float tear_stretch) {
    const int n = sheet.size;
    auto up = [&](int i, int j) { return sheet.airborne[size_t(j) * size_t(n) + size_t(i)] != 0; };
    auto pos = [&](int i, int j) { return sheet.positions[size_t(j) * size_t(n) + size_t(i)]; };
    // Torn: an edge longer than tear_stretch times the longest at rest (the diagonal),
    // or the area grown past tear_stretch squared. Both false for NaN: left out.
    const float max_edge2 = 2.0f * (tear_stretch * sheet.spacing_m) * (tear_stretch * sheet.spacing_m);
    const float max_area = tear_stretch * tear_stretch * 0.5f * sheet.spacing_m * sheet.spacing_m;
    auto intact = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        glm::vec3 ab = b - a, bc = c - b, ca = a - c;
        float longest2 = std::max({glm::dot(ab, ab), glm::dot(bc, bc), glm::dot(ca, ca)});
        return longest2 <= max_edge2 && 0.5f * glm::length(glm::cross(ab, -ca)) <= max_area;
    };
    const uint32_t base = uint32_t(vertices.size());
    const size_t first_index = indices.size();
    // Each quad's two triangles share the diagonal (i,j)-(i+1,j+1).
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            if (!up(i, j) || !up(i + 1, j + 1)) continue;
            uint32_t a = base + uint32_t(j * n + i), b = a + 1, c = a + uint32_t(n) + 1, d = a + uint32_t(n);
            glm::vec3 pa = pos(i, j), pb = pos(i + 1, j), pc = pos(i + 1, j + 1), pd = pos(i, j + 1);
            if (up(i + 1, j) && intact(pa, pb, pc)) indices.insert(indices.end(), {a, b, c});
            if (up(i, j + 1) && intact(pa, pc, pd)) indices.insert(indices.end(), {a, c, d});
        }
    if (indices.size() == first_index) return;
    std::vector<uint8_t> drawn(size_t(n) * size_t(n), 0);
    for (size_t k = first_index; k < indices.size(); ++k) ++drawn[indices[k] - base];

    vertices.reserve(vertices.size() + size_t(n) * size_t(n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            // Central differences inside, one-sided on the border. At rest the sheet lies
            // along x (i) and z (j): cross(d/dj, d/di) points up.
            const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, n - 1);
            const int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, n - 1);
            glm::vec3 du = pos(i1, j) - pos(i0, j);
            glm::vec3 dv = pos(i, j1) - pos(i, j0);
            glm::vec3 normal = glm::cross(dv, du);
            float len = glm::length(normal);
            float rest = float((i1 - i0) * (j1 - j0)) * sheet.spacing_m * sheet.spacing_m;
            float stretch = std::isfinite(len) ? len / rest : 1.0f;
            normal = (len > 1e-12f && std::isfinite(len)) ? normal / len : glm::vec3(0.0f, 1.0f, 0.0f);
            const float cover = float(drawn[size_t(j) * size_t(n) + size_t(i)]) / 6.0f;
            vertices.push_back({pos(i, j), normal, glm::vec2(float(i), float(j)), stretch, cover});
        }
}

}  // namespace effects
