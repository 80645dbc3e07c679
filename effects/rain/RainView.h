#pragma once
// What the windshield rain renderer reads of the sim (docs/effects/rain.md, "What is
// implemented"): the glass's size and shape, every drop and wiper particle as a 2D
// metaball in the glass's coordinates, the wiper blades, and where the car and the eye
// are. Gathered from the world's sim::RainSim each frame; tests and the benchmark fill
// it directly.
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace sim {
class World;
class GlassSurface;
}  // namespace sim

namespace effects {

// One splat of the height map, laid out as the splat shader's instance data.
struct RainMetaball {
    glm::vec2 centre_m{0.0f};  // glass coordinates
    float radius_m = 0.0f;
    float pad = 0.0f;
};
static_assert(sizeof(RainMetaball) == 16, "RainMetaball is uploaded as one vec4 per instance");

// Where the metaball kernel 1 / (1 + (d/R)^4) is cut off, in radii (N = 1/257 there):
// the height map's splats and its 3D reference use the same support.
constexpr float kMetaballReach = 4.0f;

struct WiperBladeView {
    glm::vec2 pivot_m{0.0f};
    glm::vec2 direction{1.0f, 0.0f};  // unit, along the arm
    float inner_m = 0.0f, outer_m = 0.0f;
};

struct RainView {
    const sim::GlassSurface* glass = nullptr;  // none: the car has no windshield
    bool driver_view = false;                  // only the driver sees the rain
    glm::mat4 car_to_world{1.0f};
    std::vector<RainMetaball> metaballs;
    std::vector<WiperBladeView> blades;
    bool wipers_parked = true;
    // The film a runner leaves: per glass cell (rows of film_cols from the lower edge,
    // cells of film_cell_m), 255 where a drop just ran, fading to 0 as it dries. Empty:
    // no film.
    std::vector<uint8_t> film;
    int film_cols = 0, film_rows = 0;
    float film_cell_m = 0.0f;

    // True when there is nothing to draw: not in the driver's seat, no glass, or a
    // dry glass with the wipers at rest.
    bool idle() const { return !glass || !driver_view || (metaballs.empty() && wipers_parked); }
};

// Refills `out` from the world's sim::RainSim (and the player and car). Reuses out's
// storage so a frame allocates nothing once warmed up.
void gather_rain_view(const sim::World& world, RainView& out);

}  // namespace effects
