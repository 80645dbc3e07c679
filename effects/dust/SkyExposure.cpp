#include "effects/dust/SkyExposure.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/dust/SourceDepthMap.h"

namespace effects {

namespace {
// The maps frame a sphere this large about each prop. A source map skips triangles
// reaching in front of its near plane, so this must exceed how far the roof's
// corners lie from the prop towards each source (~16 m in the warehouse).
constexpr float kReach_m = 25.0f;
constexpr int kMapSize = 160;  // about 30 cm texels
// Each vertex tests from this far towards the source: the maps are too coarse to
// resolve the prop's own surfaces, and the sky is hidden by what stands far above.
constexpr float kStartAbove_m = 1.0f;
}  // namespace

std::vector<float> sky_exposure(const sim::DustSurface& surface, const SceneDesc& scene) {
    std::vector<glm::vec3> directions{{0.0f, 1.0f, 0.0f}};
    for (int k = 0; k < 4; ++k) {
        const float azimuth = 1.5707963f * (float(k) + 0.5f);
        directions.push_back(glm::normalize(glm::vec3(std::cos(azimuth), 1.0f, std::sin(azimuth))));
    }
    std::vector<glm::vec3> triangles;  // world space, three corners each
    for (const PropInstance& inst : scene.props)
        for (const MeshData& mesh : scene.models[size_t(inst.model)].meshes)
            for (uint32_t i : mesh.indices) triangles.push_back(glm::vec3(inst.transform * glm::vec4(mesh.vertices[i].position, 1.0f)));
    std::vector<float> exposure(surface.positions().size(), 0.0f);
    for (const sim::DustPropRange& prop : surface.props()) {
        std::vector<sim::SourceDepthMap> maps;
        for (glm::vec3 d : directions) {
            sim::SourceDepthMap& map = maps.emplace_back(prop.centre() + d * (4.0f * kReach_m), prop.centre(), kReach_m, kMapSize);
            for (size_t t = 0; t + 2 < triangles.size(); t += 3)
                // Every direction climbs: wholly below the prop, nothing hides its sky.
                if (std::max({triangles[t].y, triangles[t + 1].y, triangles[t + 2].y}) > prop.bounds.min.y)
                    map.rasterise(triangles[t], triangles[t + 1], triangles[t + 2]);
        }
        for (uint32_t v = prop.first_vertex; v < prop.first_vertex + prop.vertex_count; ++v) {
            const glm::vec3 n = surface.normals()[v], p = surface.positions()[v];
            float seen = 0.0f, total = 0.0f;
            for (size_t k = 0; k < directions.size(); ++k) {
                const float w = std::max(glm::dot(n, directions[k]), 0.0f);
                seen += w * maps[k].visibility(p + directions[k] * kStartAbove_m);
                total += w;
            }
            exposure[v] = total > 0.0f ? seen / total : 0.0f;
        }
    }
    return exposure;
}

}  // namespace effects
