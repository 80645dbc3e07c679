#pragma once
// The tunables of the windshield rain (docs/effects/rain.md). Masses in milligrams (a
// milligram of water is a cubic millimetre), lengths in metres. Drops are a little
// heavier than most real ones (a few mm across) so that they read from the driver's
// seat at game resolutions.
#include <array>

#include <glm/vec2.hpp>

#include "sim/rain/WiperMotor.h"

namespace sim {

// Where a blade sits, in fractions of the glass (pivot u of the width, v and radii of
// the height), so the same layout fits any windshield.
struct WiperLayout {
    glm::vec2 pivot{0.2f, -0.04f};
    float inner = 0.12f, outer = 0.9f;
    float rest_rad = 0.05f, sweep_rad = 2.1f;
};

// The drop grid's cell sizes the sim runs: RainSim refuses others, and the level
// loader refuses them first, naming the level file's key.
inline constexpr float kMinRainCell_m = 0.001f, kMaxRainCell_m = 0.05f;

struct RainParams {
    float cell_size_m = 0.008f;  // in [kMinRainCell_m, kMaxRainCell_m]

    // Rain: new drops per square metre of glass per second at intensity 1, more with
    // forward speed; their masses are uniform in [min, max].
    float drops_per_m2_s = 250.0f;
    float speed_gain_per_mps = 0.05f;
    float new_drop_min_mg = 4.0f, new_drop_max_mg = 40.0f;

    // Grid model. A drop of slide_mass_mg just slides on glass raked at 45 degrees;
    // what holds a drop scales with its contact line, so per unit mass as 1 / r^2.
    float slide_mass_mg = 180.0f;
    float drag_per_s = 18.0f;             // speed relaxes to (driving - holding) / drag
    float air_start_mps = 6.0f;           // car speed from which air pushes drops
    float air_accel = 0.05f;              // m/s^2 per (m/s)^2 above the start, on a slide-mass drop
    float straight_weight = 1.0f, side_weight = 0.55f;  // ahead vs ahead-left/right, times affinity
    float trail_chance = 0.35f;           // per cell stepped
    float trail_fraction = 0.04f;         // of the mover's mass
    float trail_min_mg = 0.6f;            // no trailing drop lighter than this
    float trail_shrink_mg_per_s = 1.0f;   // trailing drops evaporate...
    float trail_vanish_mg = 0.25f;        // ...and vanish below this
    float wet_affinity = 0.6f;            // extra affinity of a cell a drop just ran through
    float wet_memory_s = 6.0f;            // fading to none over this

    // Particle model around the blades.
    float particle_mass_mg = 20.0f;
    float band_m = 0.03f;                 // particles within this of a blade stay particles
    float restitution = 0.2f;
    int collision_iterations = 1;         // pairwise pushes per tick (the seed: one)
    float defer_mass_mg = 280.0f;         // conversion back waits while a drop this heavy...
    int defer_search_cells = 2;           // ...is within this many cells of the target
    float film_fraction = 0.04f;          // of a swept drop left behind as a trailing film drop

    int max_drops = 30000;
    int max_particles = 20000;

    WiperMotorParams motor;
    // Rubber out to 0.9 of the glass height: upright, a blade reaches 0.86 of it (at
    // 0.76, 0.72: no cleared arc read from the driver's seat). The left tip runs a
    // little past the side at the end of its sweep, the right one at rest.
    std::array<WiperLayout, 2> blades = {WiperLayout{{0.2f, -0.04f}, 0.12f, 0.9f, 0.05f, 2.15f},
                                         WiperLayout{{0.62f, -0.04f}, 0.12f, 0.9f, 0.05f, 1.95f}};
};

}  // namespace sim
