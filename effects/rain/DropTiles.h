#pragma once
// Drops listed per tile of a height map, for the fast 2D path (DropHeightMap, through
// WetTiles) and the 3D references (MetaballReference, ReferenceHeightMap) alike.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/ext/vector_uint2.hpp>
#include <glm/vec2.hpp>

#include "effects/rain/RainView.h"

namespace effects {

// The drops whose support (kMetaballReach radii, radii times radius_scale) reaches
// each kTexels x kTexels tile's texel centres: the same field as over all drops, at a
// cost that grows with the glass's area. Tile (i, j) is ranges[j * cols + i] =
// (first, count) into indices, a tile's drops in their order in `drops`. Both
// references sum over these lists.
//
// `wet` holds the tiles where water can be, as runs along rows (first tile, count):
// where the sum over the tile's drops of each one's density at its nearest texel
// passes half of `threshold` (T). No texel elsewhere can reach T, so the height maps
// shade only these tiles (WetTiles).
struct DropTiles {
    static constexpr int kTexels = 16;
    int cols = 0, rows = 0;
    std::vector<glm::uvec2> ranges;
    std::vector<uint32_t> indices;
    std::vector<glm::uvec2> wet;
};
DropTiles drops_by_tile(std::span<const RainMetaball> drops, glm::vec2 glass_size_m, int width, int height,
                        float radius_scale = 1.0f, float threshold = 0.5f);

}  // namespace effects
