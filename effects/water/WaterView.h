#pragma once
// What the water renderer reads of the sim, as plain spans and values: the wave
// grid's heights, the airborne splash sheets and the spray drops. Gathered from the
// world's WaterSim each frame; tests fill it directly.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace sim {
class World;
}

namespace effects {

// The wave grid: height above sea level of cell (i, j) at heights[j * size + i],
// the cell standing at origin_xz + (i, j) * spacing_m.
struct WaveHeights {
    int size = 0;
    float spacing_m = 0.0f;
    glm::vec2 origin_xz{0.0f};
    std::span<const float> heights;

    glm::vec2 far_corner_xz() const { return origin_xz + glm::vec2(float(size - 1) * spacing_m); }
};

// One splash sheet: size x size world positions, row-major like the grid, and which
// of them are above the water (only triangles with three airborne corners are drawn).
struct SheetView {
    int size = 0;
    float spacing_m = 0.0f;  // between neighbouring vertices at rest
    std::span<const glm::vec3> positions;
    std::span<const uint8_t> airborne;
    // Where vertex (size/2, size/2) rests, vertex (i, j) resting (i - size/2, j - size/2)
    // spacings from it (sim::SplashSheet::rest_xz): with it the renderer tells the jet's
    // vertices, thrown straight up from their rest, from the crown's, thrown outward.
    std::optional<glm::vec2> centre_xz;
    // For the foam where the sheet falls back (SplashFoam): the vertices' velocities
    // (empty: not followed), the sim's index of the sheet (stable while it flies; -1:
    // none) and the gravity its vertices fly under.
    std::span<const glm::vec3> velocities;
    int id = -1;
    float gravity_mps2 = 9.81f;
    bool bow = false;  // the sheet riding ahead of the boat's bow (its foam is the wake's)
};

// One spray droplet, laid out as the sprite renderer's instance data.
struct SprayDrop {
    glm::vec3 position{0.0f};
    float radius_m = 0.0f;
};
static_assert(sizeof(SprayDrop) == 16, "SprayDrop is uploaded as one vec4 per instance");

struct WaterView {
    float sea_level_m = 0.0f;
    std::optional<WaveHeights> grid;  // none: a flat sea everywhere
    std::vector<SheetView> sheets;    // the active ones
    std::vector<SprayDrop> spray;
    // The sim's tick and its length, and World::restore_generation: the foam left where
    // splashes fell back is a function of the ticks, forgotten when the world is replaced
    // (tick -1: no history, no foam).
    int64_t tick = -1;
    float tick_s = 1.0f / 60.0f;
    uint64_t restore_generation = 0;

    // Throws std::invalid_argument saying which part is inconsistent (sizes that
    // don't match their arrays, a non-positive spacing, a non-finite placement).
    void validate() const;
};

// Refills `out` from the world's sim::WaterSim; without one, a flat sea at the level's
// sea level. Reuses out's storage so a frame allocates nothing once warmed up.
void gather_water_view(const sim::World& world, WaterView& out);

}  // namespace effects
