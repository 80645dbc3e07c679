#include "sim/dust/DustAccumulation.h"

#include <algorithm>
#include <cmath>

#include "sim/core/DetMath.h"
#include "sim/dust/SourceDepthMap.h"

namespace sim {

namespace {
constexpr float kPi = 3.14159265f;

float smoothstep(float e0, float e1, float x) {
    float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}
}  // namespace

std::vector<glm::vec3> place_dust_sources(const DustPropRange& prop, const DustDesc& desc) {
    const glm::vec3 centre = prop.centre();
    const float dist = desc.source_distance * std::max(prop.radius(), 0.05f);
    std::vector<glm::vec3> sources{centre + glm::vec3(0.0f, dist, 0.0f)};
    const int around = desc.sources_per_prop - 1;
    const float elevation = desc.source_elevation_deg * kPi / 180.0f;
    for (int k = 0; k < around; ++k) {
        float azimuth = 2.0f * kPi * (float(k) + 0.5f) / float(around);
        sources.push_back(centre + dist * glm::vec3(det::cos(elevation) * det::cos(azimuth), det::sin(elevation),
                                                    det::cos(elevation) * det::sin(azimuth)));
    }
    return sources;
}

float dust_lobe(DustKind kind, glm::vec3 n) {
    switch (kind) {
        case DustKind::Dust: {
            float up = std::max(n.y, 0.0f);
            return up * up;  // Phong exponent 2 about +y
        }
        case DustKind::Sand:  // slides off beyond ~34 degrees
            return smoothstep(0.78f, 0.9f, n.y);
        case DustKind::Mould:  // creeps up walls, not under overhangs
            return smoothstep(-0.25f, 0.7f, n.y);
    }
    return 0.0f;
}

std::vector<glm::vec3> accumulate_dust(const DustSurface& surface, size_t prop,
                                       const std::vector<DustyPropDesc>& occluders, const DustDesc& desc,
                                       std::span<float> amounts) {
    const DustPropRange& range = surface.props()[prop];
    const std::vector<glm::vec3> sources = place_dust_sources(range, desc);
    std::vector<SourceDepthMap> maps;
    maps.reserve(sources.size());
    for (glm::vec3 s : sources) {
        SourceDepthMap& map = maps.emplace_back(s, range.centre(), range.radius() * 1.05f, kSourceMapSize);
        for (const DustyPropDesc& o : occluders)
            for (size_t t = 0; t + 2 < o.indices.size(); t += 3)
                map.rasterise(o.positions[o.indices[t]], o.positions[o.indices[t + 1]], o.positions[o.indices[t + 2]]);
    }
    const auto& pos = surface.positions();
    const auto& nrm = surface.normals();
    for (uint32_t v = range.first_vertex; v < range.first_vertex + range.vertex_count; ++v) {
        float lobe = dust_lobe(range.kind, nrm[v]);
        if (lobe <= 0.0f) {
            amounts[v] = 0.0f;
            continue;
        }
        // Test a little off the surface so it does not shadow itself.
        glm::vec3 p = pos[v] + nrm[v] * 0.02f;
        // Dust falls: the source overhead counts as much as two around.
        float exposure = 2.0f * maps[0].visibility(p);
        for (size_t s = 1; s < maps.size(); ++s) exposure += maps[s].visibility(p);
        amounts[v] = lobe * exposure / float(maps.size() + 1);
    }
    return sources;
}

}  // namespace sim
