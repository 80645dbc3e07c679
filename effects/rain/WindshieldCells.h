#pragma once
// Which cells of the windshield mesh the rain shader can change (docs/effects/rain.md,
// "The pass per frame"): on dry glass away from the blades it discards every pixel, and
// on llvmpipe those pixels cost as much as the ones it keeps. A cell is shown when a
// wet tile of the height map, a film cell wet enough to show, or a blade's or arm's
// reach lies within its filtering footprint (a texel or a film cell around it), so the
// cells left out are ones where every pixel would have been discarded: the image is
// the same bit for bit (each cell is drawn as the same two triangles either way).
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "effects/rain/DropTiles.h"
#include "effects/rain/RainView.h"

namespace effects {

struct WindshieldCellGrid {
    int columns = 0, rows = 0;  // rows from the glass's lower edge
    glm::vec2 glass_size_m{0.0f};
};

struct ShownCellInputs {
    const DropTiles* tiles = nullptr;  // the height map's last tiles (their `wet` runs)
    int map_width = 0, map_height = 0;
    float film_strength = 0.0f;        // RainLook::film; 0: the film shows nowhere
    float blade_reach_m = 0.0f;        // how far from a blade's or arm's centre line it can cover a pixel
};

// Fills `shown` (columns * rows, row-major from the lower edge) with 1 where the
// windshield shader can draw, 0 where it discards every pixel.
void shown_cells(const WindshieldCellGrid& grid, const RainView& view, const ShownCellInputs& in,
                 std::vector<uint8_t>& shown);

// The shader's threshold below which the film alone draws nothing
// (shaders/rain/windshield.frag.glsl: `film <= 0.004`).
constexpr float kFilmVisible = 0.004f;

}  // namespace effects
