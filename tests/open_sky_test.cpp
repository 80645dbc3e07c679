// The ground the sky-occlusion map has nothing above (effects/scene/OpenSky), and the
// terrain's triangles split by it (split_open_sky): what the opaque pass shades without
// the map's lookup. The frames are the same to the bit (the replays' goldens check it);
// here, that the answers are conservative and the split loses no triangle.
#include <algorithm>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include <glm/common.hpp>

#include "effects/scene/OpenSky.h"
#include "effects/scene/SceneGeometry.h"
#include "effects/scene/TerrainMesh.h"
#include "game/level/LevelLoader.h"
#include "sim/world/Terrain.h"

namespace {

using Box = effects::OpenSky::Box;

// A shed 4 m across at the middle of a 100 m square of props, on ground at 0.
effects::OpenSky shed_and_square() {
    const std::vector<Box> props{{{-2.0f, 0.0f, -2.0f}, {2.0f, 3.0f, 2.0f}},
                                 {{-50.0f, 0.0f, -50.0f}, {-49.0f, 1.0f, -49.0f}},
                                 {{49.0f, 0.0f, 49.0f}, {50.0f, 1.0f, 50.0f}}};
    return effects::OpenSky(props, {-50.0f, 0.0f, -50.0f}, {50.0f, 3.0f, 50.0f}, 1024);
}

TEST(OpenSky, OpenAwayFromEveryPropAndOffTheMapButNotNearOrUnderOne) {
    const effects::OpenSky sky = shed_and_square();
    EXPECT_TRUE(sky.open({10.0f, 0.0f, 10.0f}, {12.0f, 0.5f, 12.0f}));    // open ground
    EXPECT_FALSE(sky.open({-1.0f, 0.0f, -1.0f}, {1.0f, 0.0f, 1.0f}));     // under the shed's roof
    EXPECT_FALSE(sky.open({2.05f, 0.0f, 0.0f}, {3.0f, 0.0f, 1.0f}));      // within a texel and the lift of its wall
    EXPECT_TRUE(sky.open({2.5f, 0.0f, 0.0f}, {3.0f, 0.0f, 1.0f}));        // clear of them
    EXPECT_TRUE(sky.open({200.0f, -30.0f, 0.0f}, {210.0f, -30.0f, 5.0f}));  // off the map, at any depth
    // On the map but below its floor (the props' lowest, less a metre): the far depth
    // fails there, as the shader's lookup does.
    EXPECT_FALSE(sky.open({10.0f, -3.0f, 10.0f}, {12.0f, 0.0f, 12.0f}));
    // Without props no map is framed: nothing is called open.
    EXPECT_FALSE(effects::OpenSky({}, glm::vec3(0.0f), glm::vec3(0.0f), 1024).open({10.0f, 0.0f, 10.0f}, {11.0f, 0.0f, 11.0f}));
}

TEST(OpenSky, NearAnswersAsTheWholeWithinItsBox) {
    const effects::OpenSky sky = shed_and_square();
    const effects::OpenSky near = sky.near({0.0f, 0.0f, 0.0f}, {10.0f, 3.0f, 10.0f});
    for (float x = 0.0f; x < 10.0f; x += 0.37f)
        for (float z = 0.0f; z < 10.0f; z += 0.41f) {
            const glm::vec3 lo(x, 0.0f, z), hi(x + 0.3f, 0.2f, z + 0.3f);
            EXPECT_EQ(near.open(lo, hi), sky.open(lo, hi)) << x << ", " << z;
        }
}

// Each triangle as its three indices, for comparing sets of them.
using Triangle = std::tuple<uint32_t, uint32_t, uint32_t>;
std::vector<Triangle> triangles(const effects::TerrainMesh& mesh, const effects::TerrainMesh::IndexRange& r) {
    std::vector<Triangle> out;
    for (uint32_t k = r.first; k + 2 < r.first + r.count; k += 3)
        out.emplace_back(mesh.indices[k], mesh.indices[k + 1], mesh.indices[k + 2]);
    return out;
}

TEST(OpenSky, TheHarboursGroundSplitsWithoutLosingATriangleAndStillDrawsInRuns) {
    const game::LoadedLevel level = game::load_level("harbour");
    const sim::Terrain terrain(level.sim);
    const effects::TerrainMesh whole = effects::make_terrain_mesh(terrain, 2.0f);
    std::vector<Box> props;
    for (const effects::PropInstance& p : level.scene.props)
        props.push_back(effects::world_box(level.scene.models[size_t(p.model)], p.transform));
    ASSERT_FALSE(props.empty());
    glm::vec3 lo = props[0].first, hi = props[0].second;
    for (const Box& b : props) lo = glm::min(lo, b.first), hi = glm::max(hi, b.second);
    const effects::OpenSky sky(props, lo, hi, 1024);
    effects::TerrainMesh split = whole;
    effects::split_open_sky(split, sky);

    ASSERT_EQ(split.indices.size(), whole.indices.size());
    size_t open = 0, covered = 0;
    for (size_t t = 0; t < whole.tiles.size(); ++t)
        for (int l = 0; l < whole.tiles[t].levels; ++l) {
            const auto& before = whole.tiles[t].level[size_t(l)];
            const auto& kept = split.tiles[t].level[size_t(l)];
            const auto& moved = split.tiles[t].open_level[size_t(l)];
            EXPECT_EQ(kept.count + moved.count, before.count) << "tile " << t << " level " << l;
            // The same triangles, in their order within each kind.
            std::vector<Triangle> all = triangles(whole, before), expect_kept, expect_moved;
            for (const Triangle& tri : all) {
                const glm::vec3 a = whole.vertices[std::get<0>(tri)].position, b = whole.vertices[std::get<1>(tri)].position,
                                c = whole.vertices[std::get<2>(tri)].position;
                (sky.open(glm::min(glm::min(a, b), c), glm::max(glm::max(a, b), c)) ? expect_moved : expect_kept).push_back(tri);
            }
            EXPECT_EQ(triangles(split, kept), expect_kept) << "tile " << t << " level " << l;
            EXPECT_EQ(triangles(split, moved), expect_moved) << "tile " << t << " level " << l;
            open += moved.count / 3;
            covered += kept.count / 3;
            // Side by side at one level, tiles' ranges of a kind follow each other.
            if (t + 1 < whole.tiles.size()) {
                EXPECT_EQ(kept.first + kept.count, split.tiles[t + 1].level[size_t(l)].first);
                EXPECT_EQ(moved.first + moved.count, split.tiles[t + 1].open_level[size_t(l)].first);
            }
        }
    // The harbour has open fields and props along its roads: both kinds are there.
    EXPECT_GT(open, covered / 4);
    EXPECT_GT(covered, 0u);
}

}  // namespace
