#pragma once
// Per-tile culling of energy segments: each segment's capsule of influence (its cut-off
// radius around the axis and beyond both ends) is projected to the screen, and each
// tile lists the segments whose projection can reach it. The
// pass then shades only tiles with segments, each pixel integrating only its tile's
// segments, so the cost follows the segments a pixel can see rather than all of them.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "effects/scene/Camera.h"
#include "sim/weapon/EnergySegment.h"

namespace effects {

struct EnergyTileGrid {
    static constexpr int kTilePx = 16;
    std::vector<glm::uvec4> tiles;   // tiles with segments: tile x, y, first index, count
    std::vector<uint32_t> indices;   // segment indices, per tile
    size_t pairs() const { return indices.size(); }
};

// Bins the segments for a width x height view. Without culling every tile of the
// screen lists every segment (the comparison the bench makes).
void bin_energy_segments(const Camera& camera, int width, int height, std::span<const sim::EnergySegment> segments,
                         bool cull, EnergyTileGrid& grid);

}  // namespace effects
