#pragma once
// What the sim needs to know about a level: ground, sea, solids, spawn points. Filled
// by the game's level loader from the level JSON and its glTF assets; no files here.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/dust/DustDesc.h"
#include "sim/objectives/ObjectiveDesc.h"

namespace sim {

struct Aabb {
    glm::vec3 min{0.0f}, max{0.0f};
    bool contains_xz(glm::vec2 p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.z && p.y <= max.z;
    }
};

struct Rect {  // on the ground plane: x and z
    glm::vec2 min{0.0f}, max{0.0f};
    bool contains(glm::vec2 p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y;
    }
};

struct Hill {
    glm::vec2 centre_xz{0.0f};
    float radius_m = 10.0f;  // Gaussian sigma
    float height_m = 1.0f;
};

struct Spawn {
    glm::vec3 position{0.0f};
    float heading_rad = 0.0f;  // 0 faces +x, positive turns towards -z (counter-clockwise seen from above)
};

// Where the harbour's wave grid lies (docs/effects/water.md); a level without one has a
// flat sea.
struct WaterGridDesc {
    bool enabled = false;
    glm::vec2 origin_xz{0.0f};  // world xz of cell (0, 0)
    int size = 256;             // cells per side
    float spacing_m = 0.5f;
    float wave_speed_mps = 2.5f;
    float damping_per_s = 0.25f;
};

// The windshield rain's glass (docs/effects/rain.md): the car's windshield as two polylines
// in car model space, its lower and upper edge from the car's left to its right, the
// glass ruled between them; and the size of the drop grid's square cells.
struct RainDesc {
    float cell_size_m = 0.008f;
    std::vector<glm::vec3> glass_lower, glass_upper;  // empty: the car has no windshield
};

// The glass tank of particle liquid (docs/effects/fluid.md). The smoothing fields are read
// by the renderer (effects/fluid), not the sim; the loader checks them.
struct FluidTankDesc {
    bool enabled = false;
    bool on_boat = false;                  // rides the boat's deck instead of the pier
    glm::vec3 inner_size_m{1.6f, 1.1f, 1.6f};  // filled from the floor up at the rest spacing
    float particle_radius_m = 0.04f;
    int particle_count = 2400;             // a tick within 6 ms on 2 idle cores (spindrift bench)
    int solver_iterations = 3;
    int body_neighbours = 12;              // fewer neighbours than this: splash
    std::string smoothing = "plane_fit";   // "plane_fit" | "bilateral" | "narrow_range"
    int kernel_size = 9;                   // odd, pixels
    int smoothing_iterations = 3;
};

struct LevelDesc {
    std::string id;
    uint64_t seed = 1;

    // Ground: land where z < shore_z_m at land_height_m plus hills; sea bed beyond.
    float half_extent_m = 160.0f;  // the world is [-h, h] in x and z
    float land_height_m = 1.2f;
    float shore_z_m = 0.0f;
    float sea_level_m = 0.0f;
    float seabed_m = -6.0f;
    std::vector<Hill> hills;
    std::vector<Rect> roads;  // better tyre grip than the rest of the land

    // Boxes that vehicles and thrown objects collide with (walls, crates, pilings).
    std::vector<Aabb> solids;
    // Boxes whose tops can be driven on (the pier deck).
    std::vector<Aabb> decks;

    Spawn car_spawn;
    Spawn boat_spawn;
    glm::vec3 tank_spot{0.0f};  // where the fluid tank stands

    glm::vec3 sun_direction{0.4f, 0.8f, 0.3f};  // towards the sun, normalised by the loader
    float rain_intensity = 0.0f;                // 0..1 at start
    RainDesc rain;
    WaterGridDesc water;
    FluidTankDesc fluid;
    DustDesc dust;  // the dusty props (docs/effects/dust.md)
    ObjectivesDesc objectives;  // courses and targets (README, Playing)
};

}  // namespace sim
