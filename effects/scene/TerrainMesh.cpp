#include "effects/scene/TerrainMesh.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace effects {

Model make_terrain_model(const sim::Terrain& terrain, float spacing_m) {
    const sim::LevelDesc& level = terrain.level();
    const float h = level.half_extent_m;
    std::vector<float> xs, zs;
    for (float x = -h; x <= h + 1e-3f; x += spacing_m) xs.push_back(x);
    for (float z = -h; z <= h + 1e-3f; z += spacing_m) zs.push_back(z);
    // Rows exactly on both edges of the quay.
    for (float z : {level.shore_z_m, level.shore_z_m + 1.0f}) zs.push_back(z);
    std::sort(zs.begin(), zs.end());
    zs.erase(std::unique(zs.begin(), zs.end(), [](float a, float b) { return std::fabs(a - b) < 0.05f; }), zs.end());

    // Tiles of kTileCells x kTileCells cells, each its own mesh with its own bounds, so
    // the passes skip what their view cannot see. Edge vertices are repeated, bit for bit.
    constexpr size_t kTileCells = 16;
    const size_t nx = xs.size(), nz = zs.size();
    auto vertex = [&](float x, float z) {
        float e = 0.25f;
        float dx = terrain.ground_height({x + e, z}) - terrain.ground_height({x - e, z});
        float dz = terrain.ground_height({x, z + e}) - terrain.ground_height({x, z - e});
        glm::vec3 n = glm::normalize(glm::vec3(-dx / (2 * e), 1.0f, -dz / (2 * e)));
        return MeshVertex{{x, terrain.ground_height({x, z}), z}, n, glm::vec4(1.0f)};
    };
    std::vector<MeshData> tiles;
    for (size_t j0 = 0; j0 + 1 < nz; j0 += kTileCells)
        for (size_t i0 = 0; i0 + 1 < nx; i0 += kTileCells) {
            const size_t j1 = std::min(j0 + kTileCells, nz - 1), i1 = std::min(i0 + kTileCells, nx - 1);
            const size_t w = i1 - i0 + 1;
            MeshData m;
            m.name = "terrain";
            m.roughness = 0.9f;
            for (size_t j = j0; j <= j1; ++j)
                for (size_t i = i0; i <= i1; ++i) m.vertices.push_back(vertex(xs[i], zs[j]));
            const bool flat = std::all_of(m.vertices.begin(), m.vertices.end(), [&](const MeshVertex& v) {
                return v.position.y == m.vertices.front().position.y && v.normal == glm::vec3(0.0f, 1.0f, 0.0f);
            });
            if (flat) {
                // Level ground: a fan from the centre to the border's vertices, the same as
                // the grid's pixel for pixel but an eighth of its triangles (every one is
                // set up on the CPU). The border keeps every vertex: no T-junctions.
                const size_t h = j1 - j0 + 1;
                std::vector<uint32_t> ring;
                for (size_t i = 0; i + 1 < w; ++i) ring.push_back(uint32_t(i));
                for (size_t j = 0; j + 1 < h; ++j) ring.push_back(uint32_t(j * w + w - 1));
                for (size_t i = w - 1; i > 0; --i) ring.push_back(uint32_t((h - 1) * w + i));
                for (size_t j = h - 1; j > 0; --j) ring.push_back(uint32_t(j * w));
                MeshVertex centre = m.vertices.front();
                centre.position.x = 0.5f * (xs[i0] + xs[i1]);
                centre.position.z = 0.5f * (zs[j0] + zs[j1]);
                const uint32_t c = uint32_t(m.vertices.size());
                m.vertices.push_back(centre);
                for (size_t k = 0; k < ring.size(); ++k)
                    m.indices.insert(m.indices.end(), {c, ring[(k + 1) % ring.size()], ring[k]});
            } else {
                for (size_t j = 0; j + 1 < j1 - j0 + 1; ++j)
                    for (size_t i = 0; i + 1 < w; ++i) {
                        uint32_t a = uint32_t(j * w + i), b = a + 1, c = uint32_t(a + w), d = c + 1;
                        m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
                    }
            }
            tiles.push_back(std::move(m));
        }
    Model model;
    model.name = "terrain";
    model.bounds_min = {-h, level.seabed_m, -h};
    model.bounds_max = {h, level.land_height_m + 20.0f, h};
    model.meshes = std::move(tiles);
    return model;
}

Model make_sea_model(float sea_level_m, float half_extent_m) {
    MeshData m;
    m.name = "sea";
    float e = half_extent_m;
    for (glm::vec2 p : {glm::vec2(-e, -e), glm::vec2(e, -e), glm::vec2(-e, e), glm::vec2(e, e)})
        m.vertices.push_back({{p.x, sea_level_m, p.y}, {0, 1, 0}, glm::vec4(1.0f)});
    m.indices = {0, 2, 1, 1, 2, 3};
    Model model;
    model.name = "sea";
    model.meshes.push_back(std::move(m));
    model.bounds_min = {-e, sea_level_m, -e};
    model.bounds_max = {e, sea_level_m, e};
    return model;
}

}  // namespace effects
