// The ground's levels of detail (effects/scene/TerrainMesh): every level of a tile covers
// the tile once and keeps every vertex of its border (so tiles at different levels meet
// without cracks), level ground costs a fan at its coarsest, and a tile is drawn finer
// the nearer the eye. On the harbour level's own terrain.
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "effects/scene/TerrainMesh.h"
#include "game/level/LevelLoader.h"
#include "sim/world/Terrain.h"

namespace {

struct Harbour {
    game::LoadedLevel level = game::load_level("harbour");
    sim::Terrain terrain{level.sim};
    effects::TerrainMesh mesh = effects::make_terrain_mesh(terrain, 2.0f);
};

const Harbour& harbour() {
    static const Harbour h;
    return h;
}

// The xz area a level's triangles of a tile cover (each counted with its sign: a
// triangle wound the other way would cancel instead of adding).
double covered_area(const effects::TerrainMesh& mesh, const effects::TerrainMesh::IndexRange& r) {
    double area = 0.0;
    for (uint32_t k = r.first; k + 2 < r.first + r.count; k += 3) {
        const glm::vec3 a = mesh.vertices[mesh.indices[k]].position, b = mesh.vertices[mesh.indices[k + 1]].position,
                        c = mesh.vertices[mesh.indices[k + 2]].position;
        area += 0.5 * (double(b.x - a.x) * double(c.z - a.z) - double(c.x - a.x) * double(b.z - a.z));
    }
    return area;
}

TEST(TerrainLod, EveryLevelCoversItsTileOnceWoundAsTheFinestAndKeepsTheBorder) {
    const effects::TerrainMesh& mesh = harbour().mesh;
    ASSERT_FALSE(mesh.tiles.empty());
    int coarse_levels = 0;
    for (size_t t = 0; t < mesh.tiles.size(); ++t) {
        const effects::TerrainMesh::Tile& tile = mesh.tiles[t];
        const double finest = covered_area(mesh, tile.level[0]);
        ASSERT_NE(finest, 0.0);
        EXPECT_NEAR(std::fabs(finest), double(tile.hi.x - tile.lo.x) * double(tile.hi.z - tile.lo.z), 1e-2) << "tile " << t;
        // The border's vertices: those of the finest level on the tile's box edges.
        std::set<uint32_t> border;
        for (uint32_t k = tile.level[0].first; k < tile.level[0].first + tile.level[0].count; ++k) {
            const glm::vec3 p = mesh.vertices[mesh.indices[k]].position;
            if (p.x == tile.lo.x || p.x == tile.hi.x || p.z == tile.lo.z || p.z == tile.hi.z) border.insert(mesh.indices[k]);
        }
        EXPECT_EQ(tile.error_m[0], 0.0f);
        for (int l = 1; l < tile.levels; ++l) {
            ++coarse_levels;
            const effects::TerrainMesh::IndexRange r = tile.level[size_t(l)];
            EXPECT_LT(r.count, tile.level[size_t(l - 1)].count) << "tile " << t << " level " << l;
            EXPECT_NEAR(covered_area(mesh, r), finest, 1e-2) << "tile " << t << " level " << l;
            std::set<uint32_t> used(mesh.indices.begin() + r.first, mesh.indices.begin() + r.first + r.count);
            for (uint32_t v : border) EXPECT_TRUE(used.contains(v)) << "tile " << t << " level " << l << " drops a border vertex";
            EXPECT_GE(tile.error_m[size_t(l)], 0.0f);
        }
    }
    EXPECT_GT(coarse_levels, int(mesh.tiles.size()));
}

// Level ground facing straight up (no hill's foot within a normal's reach).
bool level_and_up(const effects::TerrainMesh& mesh, const effects::TerrainMesh::Tile& tile) {
    for (uint32_t k = tile.level[0].first; k < tile.level[0].first + tile.level[0].count; ++k) {
        const effects::MeshVertex& v = mesh.vertices[mesh.indices[k]];
        if (v.position.y != tile.lo.y || v.normal != glm::vec3(0.0f, 1.0f, 0.0f)) return false;
    }
    return true;
}

TEST(TerrainLod, LevelGroundIsExactAtItsCoarsestAndHillsAreNot) {
    const effects::TerrainMesh& mesh = harbour().mesh;
    int level_tiles = 0, hill_tiles = 0;
    for (const effects::TerrainMesh::Tile& tile : mesh.tiles) {
        if (tile.levels != effects::TerrainMesh::kLevels) continue;
        const float coarsest = tile.error_m[effects::TerrainMesh::kLevels - 1];
        if (level_and_up(mesh, tile)) {
            ++level_tiles;
            EXPECT_EQ(coarsest, 0.0f);
            EXPECT_EQ(tile.level[effects::TerrainMesh::kLevels - 1].count, 64u * 3u);  // a fan around 64 border edges
        } else if (tile.hi.y - tile.lo.y > 1.0f) {
            ++hill_tiles;
            EXPECT_GT(coarsest, 0.0f);
        }
    }
    EXPECT_GT(level_tiles, 0);
    EXPECT_GT(hill_tiles, 0);
}

TEST(TerrainLod, ATileIsDrawnFinerTheNearerTheEyeAndTheSharperThePicture) {
    const effects::TerrainMesh& mesh = harbour().mesh;
    // The hill's tile whose next level strays most (and finitely) from the finest.
    const effects::TerrainMesh::Tile* hill = nullptr;
    for (const effects::TerrainMesh::Tile& tile : mesh.tiles)
        if (tile.levels == effects::TerrainMesh::kLevels && std::isfinite(tile.error_m[1]) &&
            (!hill || tile.error_m[1] > hill->error_m[1]))
            hill = &tile;
    ASSERT_NE(hill, nullptr);
    const glm::vec3 centre = 0.5f * (hill->lo + hill->hi);
    const float ppr = 0.5f * 1.732f * 252.0f;  // 60 degrees over 252 rows
    ASSERT_GT(hill->error_m[1], 0.05f);
    const int near = hill->level_for(glm::vec3(centre.x, hill->hi.y + 2.0f, centre.z), ppr, 0.5f);
    const int far = hill->level_for(centre + glm::vec3(0.0f, 2.0f, 5000.0f), ppr, 0.5f);
    EXPECT_EQ(near, 0);
    EXPECT_GT(far, near);
    EXPECT_LE(hill->error_m[size_t(far)] * ppr / 5000.0f, 0.5f);
    EXPECT_LE(hill->level_for(centre + glm::vec3(0.0f, 2.0f, 5000.0f), 4.0f * ppr, 0.5f), far);
}

}  // namespace
