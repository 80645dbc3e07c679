#include "effects/water/SplashSheetMesh.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include <glm/geometric.hpp>

namespace effects {

void SplashSheetMesh::append(const SheetView& sheet, float tear_stretch, float sea_level_m) {
    const int n = sheet.size;
    const size_t count = size_t(n) * size_t(n);
    auto at = [&](int i, int j) { return size_t(j) * size_t(n) + size_t(i); };
    auto up = [&](int i, int j) { return sheet.airborne[at(i, j)] != 0; };

    // The jet's vertices, drawn pulled in towards its axis (kJetSqueeze).
    jet_.assign(count, 0);
    shown_.assign(sheet.positions.begin(), sheet.positions.end());
    if (sheet.centre_xz) {
        const glm::vec2 axis = *sheet.centre_xz;
        const int half = n / 2;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const size_t k = at(i, j);
                const glm::vec3 p = sheet.positions[k];
                const float height = p.y - sea_level_m;
                const glm::vec2 rest = axis + glm::vec2(float(i - half), float(j - half)) * sheet.spacing_m;
                const glm::vec2 xz(p.x, p.z);
                if (!up(i, j) || !(height > kJetLowM) || glm::distance(xz, rest) >= kJetMaxLean * height) continue;
                jet_[k] = 1;
                const float t = std::min((height - kJetLowM) / (kJetHighM - kJetLowM), 1.0f);
                const float squeeze = 1.0f - (1.0f - kJetSqueeze) * t * t * (3.0f - 2.0f * t);
                const glm::vec2 drawn_xz = axis + (xz - axis) * squeeze;
                shown_[k] = {drawn_xz.x, p.y, drawn_xz.y};
            }
    }
    auto pos = [&](int i, int j) { return shown_[at(i, j)]; };
    // A triangle of the jet and the crown together would span the gap the squeeze opened.
    auto one_part = [&](size_t a, size_t b, size_t c) { return jet_[a] == jet_[b] && jet_[b] == jet_[c]; };

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
            const size_t ka = at(i, j), kb = at(i + 1, j), kc = at(i + 1, j + 1), kd = at(i, j + 1);
            uint32_t a = base + uint32_t(ka), b = base + uint32_t(kb), c = base + uint32_t(kc), d = base + uint32_t(kd);
            glm::vec3 pa = shown_[ka], pb = shown_[kb], pc = shown_[kc], pd = shown_[kd];
            if (up(i + 1, j) && one_part(ka, kb, kc) && intact(pa, pb, pc)) indices.insert(indices.end(), {a, b, c});
            if (up(i, j + 1) && one_part(ka, kc, kd) && intact(pa, pc, pd)) indices.insert(indices.end(), {a, c, d});
        }
    if (indices.size() == first_index) return;
    const size_t sheet_indices_end = indices.size();

    // The column's side: each edge of the jet's outline carried straight down into the
    // water, so the jet stands in it rather than hanging as a hood.
    auto jet = [&](int i, int j) { return i >= 0 && j >= 0 && i < n && j < n && jet_[at(i, j)] != 0; };
    std::vector<std::pair<size_t, size_t>>& foot = foot_;
    foot.clear();
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if (!jet(i, j)) continue;
            // Along i: outline where the rows on either side are not both jet.
            if (jet(i + 1, j) && !(jet(i, j - 1) && jet(i + 1, j - 1) && jet(i, j + 1) && jet(i + 1, j + 1)))
                foot.push_back({at(i, j), at(i + 1, j)});
            if (jet(i, j + 1) && !(jet(i - 1, j) && jet(i - 1, j + 1) && jet(i + 1, j) && jet(i + 1, j + 1)))
                foot.push_back({at(i, j), at(i, j + 1)});
        }

    drawn_.assign(count, 0);
    for (size_t k = first_index; k < sheet_indices_end; ++k) ++drawn_[indices[k] - base];
    for (const auto& [ea, eb] : foot) drawn_[ea] = drawn_[eb] = 6;  // held by the side: not a free edge

    vertices.reserve(vertices.size() + count + 2 * foot.size());
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
            if (jet_[at(i, j)]) stretch = 1.0f;  // the column is solid water, not film thinned by the squeeze
            const float cover = std::min(float(drawn_[at(i, j)]) / 6.0f, 1.0f);
            vertices.push_back({pos(i, j), normal, glm::vec2(float(i), float(j)), stretch, cover});
        }
    add_drops(sheet, sea_level_m, base, first_index, sheet_indices_end);
    for (const auto& [ea, eb] : foot) {
        const uint32_t a = base + uint32_t(ea), b = base + uint32_t(eb);
        const uint32_t fa = uint32_t(vertices.size()), fb = fa + 1;
        for (uint32_t top : {a, b}) {
            SheetVertex v = vertices[top];
            const glm::vec2 out(v.position.x - sheet.centre_xz->x, v.position.z - sheet.centre_xz->y);
            if (glm::dot(out, out) > 1e-12f) v.normal = glm::normalize(glm::vec3(out.x, 0.0f, out.y));
            vertices[top].normal = v.normal;
            // The column widens towards its foot, where it rises out of the water.
            v.position.x = sheet.centre_xz->x + out.x * kJetFootFlare;
            v.position.z = sheet.centre_xz->y + out.y * kJetFootFlare;
            v.position.y = sea_level_m - kJetFootDepthM;
            vertices.push_back(v);
        }
        indices.insert(indices.end(), {a, b, fb, a, fb, fa});
    }
}

void SplashSheetMesh::add_drops(const SheetView& sheet, float sea_level_m, uint32_t base, size_t first_index,
                                size_t end_index) {
    // A hash in [0, 1) of two numbers fixed in the film.
    auto hash01 = [](uint32_t a, uint32_t b) {
        uint32_t h = a * 0x8da6b343u ^ b * 0xd8163841u;
        h ^= h >> 15;
        h *= 0x2c1b3c6du;
        h ^= h >> 12;
        return float(h >> 8) / float(1u << 24);
    };
    // The free edges: those of exactly one drawn triangle of the film (not the jet's).
    edges_.clear();
    for (size_t t = first_index; t + 2 < end_index; t += 3)
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = indices[t + size_t(e)] - base, b = indices[t + size_t((e + 1) % 3)] - base;
            if (jet_[a] || jet_[b]) continue;
            edges_.push_back(uint64_t(std::min(a, b)) << 32 | std::max(a, b));
        }
    std::sort(edges_.begin(), edges_.end());
    for (size_t e = 0; e < edges_.size(); ++e) {
        if ((e > 0 && edges_[e - 1] == edges_[e]) || (e + 1 < edges_.size() && edges_[e + 1] == edges_[e])) continue;
        const uint32_t a = uint32_t(edges_[e] >> 32), b = uint32_t(edges_[e]);
        const glm::vec3 pa = vertices[base + a].position, pb = vertices[base + b].position;
        if (std::min(pa.y, pb.y) - sea_level_m < 0.08f) continue;  // where it meets the sea: the collar
        const int beads = int(glm::distance(pa, pb) / kBeadSpacingM + hash01(a, b));
        for (int k = 0; k < beads; ++k) {
            const float h = hash01(a + uint32_t(k) * 7919u, b);
            const float r = kBeadMinM + (kBeadMaxM - kBeadMinM) * h;
            const float along = (float(k) + 0.25f + 0.5f * hash01(b, a + uint32_t(k))) / float(beads);
            drops.push_back({glm::mix(pa, pb, along) + glm::vec3(0.0f, 0.6f * r, 0.0f), r});
        }
    }

    // The jet's top: its highest drawn vertex.
    const int n = sheet.size;
    float jet_top = -1e30f;
    glm::vec3 top(0.0f);
    for (size_t k = 0; k < size_t(n) * size_t(n); ++k)
        if (jet_[k] && drawn_[k] > 0 && vertices[base + k].position.y > jet_top)
            jet_top = vertices[base + k].position.y, top = vertices[base + k].position;
    if (!sheet.centre_xz || jet_top - sea_level_m < kTopDropJetM) return;
    // The column's radius at its top: the widest drawn jet vertex within 10 cm of it.
    const glm::vec2 axis = *sheet.centre_xz;
    float radius = 0.0f;
    for (size_t k = 0; k < jet_.size(); ++k) {
        const glm::vec3 p = vertices[base + k].position;
        if (jet_[k] && drawn_[k] > 0 && p.y > jet_top - 0.1f) radius = std::max(radius, glm::distance(glm::vec2(p.x, p.z), axis));
    }
    const float r = std::max(kTopDropShare * radius, kTopDropMinM);
    // Just clear of the column's rounded top, the neck between them pinching shut.
    drops.push_back({glm::vec3(top.x, jet_top + 1.6f * r, top.z), r});
}

}  // namespace effects
