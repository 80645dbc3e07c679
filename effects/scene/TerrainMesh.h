#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "effects/scene/OpenSky.h"
#include "effects/scene/SceneDesc.h"
#include "sim/world/Terrain.h"

namespace effects {

// The ground as a height-field mesh sampled from the sim's terrain, with rows on the quay
// edge so the drop to the sea bed stays sharp, in square tiles (each with its own bounds,
// so the passes skip what their view cannot see). Colours come from the shader.
//
// Each tile has its triangles at up to five levels of detail: every grid cell (level 0),
// then cells of 2, 4, 8 and 16 grid cells a side. A coarser level keeps every vertex of
// the tile's border (its border cells are fans from their centre to those vertices), so
// a tile at any level meets its neighbours at any level without cracks or T-junctions.
// Each level records how far (metres, vertically) it strays from the finest, for the
// renderer to pick per tile the coarsest whose error stays under a pixel.
struct TerrainMesh {
    static constexpr int kLevels = 5;
    struct IndexRange {
        uint32_t first = 0, count = 0;  // into `indices`
    };
    struct Tile {
        glm::vec3 lo{0.0f}, hi{0.0f};
        int levels = 1;  // how many of `level` hold triangles (coarser ones only where the cells divide the tile)
        std::array<IndexRange, kLevels> level{};
        // After split_open_sky: the triangles of each level open to the sky, apart from
        // `level`'s (empty until then).
        std::array<IndexRange, kLevels> open_level{};
        std::array<float, kLevels> error_m{};  // the largest vertical gap to level 0's surface

        // The coarsest level whose error, seen from `eye` at the tile's nearest point,
        // is at most `max_error_px` pixels (`pixels_per_radian`: viewport height /
        // (2 tan(fov_y / 2))).
        int level_for(glm::vec3 eye, float pixels_per_radian, float max_error_px) const;
    };
    std::vector<MeshVertex> vertices;
    // Level-major: every tile's level 0, then every tile's level 1... (after
    // split_open_sky, each level's open triangles after all its others).
    std::vector<uint32_t> indices;
    std::vector<Tile> tiles;
    float roughness = 0.9f;
};

TerrainMesh make_terrain_mesh(const sim::Terrain& terrain, float spacing_m);

// Moves each tile's triangles that `open` answers for (by the triangle's box; OpenSky, its
// props those near the tile) from Tile::level to Tile::open_level, keeping their order.
// Per level every tile's other triangles come first, then every tile's open ones, so
// that tiles side by side still make one draw of each kind.
void split_open_sky(TerrainMesh& mesh, const OpenSky& open);

// A large flat quad at sea level reaching the horizon.
Model make_sea_model(float sea_level_m, float half_extent_m);

}  // namespace effects
