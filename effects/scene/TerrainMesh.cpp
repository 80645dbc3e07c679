#include "effects/scene/TerrainMesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace effects {

namespace {

constexpr size_t kTileCells = 16;

// A tile's triangles with cells of `stride` grid cells a side, over its w x h vertices
// (row-major, local indices). Cells on the tile's border are fans from their centre
// vertex around every border vertex on their edge; the others are two triangles.
// Winding as the finest level: (i, j), (i, j + 1), (i + 1, j).
std::vector<uint32_t> tile_triangles(size_t w, size_t h, size_t stride) {
    auto at = [w](size_t i, size_t j) { return uint32_t(j * w + i); };
    std::vector<uint32_t> out;
    const size_t last_i = w - 1, last_j = h - 1;
    for (size_t b = 0; b < last_j; b += stride)
        for (size_t a = 0; a < last_i; a += stride) {
            const size_t a1 = a + stride, b1 = b + stride;
            const bool border = stride > 1 && (a == 0 || b == 0 || a1 == last_i || b1 == last_j);
            if (!border) {
                out.insert(out.end(), {at(a, b), at(a, b1), at(a1, b), at(a1, b), at(a, b1), at(a1, b1)});
                continue;
            }
            // The cell's outline counter-clockwise in (i, j), fine along the tile's border.
            std::vector<uint32_t> ring;
            const size_t fine_b = b == 0 ? 1 : stride, fine_r = a1 == last_i ? 1 : stride;
            const size_t fine_t = b1 == last_j ? 1 : stride, fine_l = a == 0 ? 1 : stride;
            for (size_t i = a; i < a1; i += fine_b) ring.push_back(at(i, b));
            for (size_t j = b; j < b1; j += fine_r) ring.push_back(at(a1, j));
            for (size_t i = a1; i > a; i -= fine_t) ring.push_back(at(i, b1));
            for (size_t j = b1; j > b; j -= fine_l) ring.push_back(at(a, j));
            const uint32_t centre = at(a + stride / 2, b + stride / 2);
            for (size_t k = 0; k < ring.size(); ++k) out.insert(out.end(), {centre, ring[(k + 1) % ring.size()], ring[k]});
        }
    return out;
}

// How far the surface of `coarse` (local indices over `v`) strays vertically from the
// tile's vertices: each vertex against the coarse triangles over it. Infinite where the
// normal shaded there would stray from the vertex's own by more than about a degree: the
// ground is shaded from its interpolated normals, and a coarse triangle spread over a
// slope's edge (the quay's drop) would shade flat ground as slope.
float vertical_error(const std::vector<MeshVertex>& v, const std::vector<uint32_t>& coarse) {
    constexpr float kNormalTolerance = 0.02f;  // |n - n'| of unit normals, radians nearly
    float worst = 0.0f;
    for (size_t t = 0; t + 2 < coarse.size(); t += 3) {
        const MeshVertex &v0 = v[coarse[t]], &v1 = v[coarse[t + 1]], &v2 = v[coarse[t + 2]];
        const glm::vec3 p0 = v0.position, p1 = v1.position, p2 = v2.position;
        const glm::vec2 lo = glm::min(glm::vec2(p0.x, p0.z), glm::min(glm::vec2(p1.x, p1.z), glm::vec2(p2.x, p2.z)));
        const glm::vec2 hi = glm::max(glm::vec2(p0.x, p0.z), glm::max(glm::vec2(p1.x, p1.z), glm::vec2(p2.x, p2.z)));
        const float det = (p1.x - p0.x) * (p2.z - p0.z) - (p2.x - p0.x) * (p1.z - p0.z);
        if (std::fabs(det) < 1e-9f) continue;
        for (const MeshVertex& q : v) {
            const glm::vec3 p = q.position;
            if (p.x < lo.x || p.x > hi.x || p.z < lo.y || p.z > hi.y) continue;
            const float u = ((p.x - p0.x) * (p2.z - p0.z) - (p2.x - p0.x) * (p.z - p0.z)) / det;
            const float w = ((p1.x - p0.x) * (p.z - p0.z) - (p.x - p0.x) * (p1.z - p0.z)) / det;
            if (u < -1e-4f || w < -1e-4f || u + w > 1.0f + 1e-4f) continue;
            const float y = p0.y + u * (p1.y - p0.y) + w * (p2.y - p0.y);
            const glm::vec3 n = glm::normalize(v0.normal + u * (v1.normal - v0.normal) + w * (v2.normal - v0.normal));
            if (glm::length(n - q.normal) > kNormalTolerance) return std::numeric_limits<float>::infinity();
            worst = std::max(worst, std::fabs(y - p.y));
        }
    }
    return worst;
}

}  // namespace

int TerrainMesh::Tile::level_for(glm::vec3 eye, float pixels_per_radian, float max_error_px) const {
    const float distance = std::max(glm::distance(eye, glm::clamp(eye, lo, hi)), 1e-3f);
    const float max_error_m = max_error_px * distance / pixels_per_radian;
    int l = 0;
    while (l + 1 < levels && error_m[size_t(l + 1)] <= max_error_m) ++l;
    return l;
}

TerrainMesh make_terrain_mesh(const sim::Terrain& terrain, float spacing_m) {
    const sim::LevelDesc& level = terrain.level();
    const float h = level.half_extent_m;
    std::vector<float> xs, zs;
    for (float x = -h; x <= h + 1e-3f; x += spacing_m) xs.push_back(x);
    for (float z = -h; z <= h + 1e-3f; z += spacing_m) zs.push_back(z);
    // Rows exactly on both edges of the quay.
    for (float z : {level.shore_z_m, level.shore_z_m + 1.0f}) zs.push_back(z);
    std::sort(zs.begin(), zs.end());
    zs.erase(std::unique(zs.begin(), zs.end(), [](float a, float b) { return std::fabs(a - b) < 0.05f; }), zs.end());

    const size_t nx = xs.size(), nz = zs.size();
    auto vertex = [&](float x, float z) {
        float e = 0.25f;
        float dx = terrain.ground_height({x + e, z}) - terrain.ground_height({x - e, z});
        float dz = terrain.ground_height({x, z + e}) - terrain.ground_height({x, z - e});
        glm::vec3 n = glm::normalize(glm::vec3(-dx / (2 * e), 1.0f, -dz / (2 * e)));
        return MeshVertex{{x, terrain.ground_height({x, z}), z}, n, glm::vec4(1.0f)};
    };
    TerrainMesh mesh;
    // Per level, per tile: the triangles (global indices), laid out level-major below.
    std::array<std::vector<std::vector<uint32_t>>, TerrainMesh::kLevels> levels;
    // Edge vertices are repeated, bit for bit, in each tile that has them.
    for (size_t j0 = 0; j0 + 1 < nz; j0 += kTileCells)
        for (size_t i0 = 0; i0 + 1 < nx; i0 += kTileCells) {
            const size_t j1 = std::min(j0 + kTileCells, nz - 1), i1 = std::min(i0 + kTileCells, nx - 1);
            const size_t w = i1 - i0 + 1, rows = j1 - j0 + 1;
            std::vector<MeshVertex> local;
            for (size_t j = j0; j <= j1; ++j)
                for (size_t i = i0; i <= i1; ++i) local.push_back(vertex(xs[i], zs[j]));
            TerrainMesh::Tile tile;
            tile.lo = tile.hi = local.front().position;
            for (const MeshVertex& v : local) {
                tile.lo = glm::min(tile.lo, v.position);
                tile.hi = glm::max(tile.hi, v.position);
            }
            const uint32_t base = uint32_t(mesh.vertices.size());
            for (int l = 0; l < TerrainMesh::kLevels; ++l) {
                const size_t stride = size_t(1) << l;
                std::vector<uint32_t> tris;
                if ((w - 1) % stride == 0 && (rows - 1) % stride == 0) {
                    tris = tile_triangles(w, rows, stride);
                    tile.error_m[size_t(l)] = l == 0 ? 0.0f : vertical_error(local, tris);
                    tile.levels = l + 1;
                }
                for (uint32_t& i : tris) i += base;
                levels[size_t(l)].push_back(std::move(tris));
            }
            mesh.vertices.insert(mesh.vertices.end(), local.begin(), local.end());
            mesh.tiles.push_back(tile);
        }
    for (int l = 0; l < TerrainMesh::kLevels; ++l)
        for (size_t t = 0; t < mesh.tiles.size(); ++t) {
            const std::vector<uint32_t>& tris = levels[size_t(l)][t];
            mesh.tiles[t].level[size_t(l)] = {uint32_t(mesh.indices.size()), uint32_t(tris.size())};
            mesh.indices.insert(mesh.indices.end(), tris.begin(), tris.end());
        }
    return mesh;
}

void split_open_sky(TerrainMesh& mesh, const OpenSky& open) {
    std::vector<uint32_t> indices;
    indices.reserve(mesh.indices.size());
    std::vector<OpenSky> near;  // per tile, the props that can matter to it: once, for every level
    near.reserve(mesh.tiles.size());
    for (const TerrainMesh::Tile& tile : mesh.tiles) near.push_back(open.near(tile.lo, tile.hi));
    for (int l = 0; l < TerrainMesh::kLevels; ++l) {
        std::vector<std::vector<uint32_t>> open_tris(mesh.tiles.size());
        for (size_t t = 0; t < mesh.tiles.size(); ++t) {
            TerrainMesh::Tile& tile = mesh.tiles[t];
            const uint32_t first = uint32_t(indices.size());
            for (const TerrainMesh::IndexRange& r : {tile.level[size_t(l)], tile.open_level[size_t(l)]})
                for (uint32_t i = r.first; i < r.first + r.count; i += 3) {
                    const glm::vec3 a = mesh.vertices[mesh.indices[i]].position, b = mesh.vertices[mesh.indices[i + 1]].position,
                                    c = mesh.vertices[mesh.indices[i + 2]].position;
                    const bool is_open = near[t].open(glm::min(glm::min(a, b), c), glm::max(glm::max(a, b), c));
                    std::vector<uint32_t>& to = is_open ? open_tris[t] : indices;
                    to.insert(to.end(), mesh.indices.begin() + i, mesh.indices.begin() + i + 3);
                }
            tile.level[size_t(l)] = {first, uint32_t(indices.size()) - first};
        }
        for (size_t t = 0; t < mesh.tiles.size(); ++t) {
            mesh.tiles[t].open_level[size_t(l)] = {uint32_t(indices.size()), uint32_t(open_tris[t].size())};
            indices.insert(indices.end(), open_tris[t].begin(), open_tris[t].end());
        }
    }
    mesh.indices = std::move(indices);
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
