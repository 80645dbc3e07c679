#pragma once
// What the frame works out once, before the passes run, for every pass that needs it:
// the weather's look, the sky under it, where the sun's shadow map and the sky-occlusion
// map look from, the shots in flight and the line lights they make. The passes receive
// it read-only through FrameContext::data; the functions that make it need no GL.
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "effects/energy/EnergyView.h"
#include "effects/scene/Camera.h"
#include "effects/scene/WeatherLook.h"
#include "sim/world/World.h"

namespace effects {

// The sun's radiance on a clear day.
inline constexpr glm::vec3 kClearSunRadiance{3.2f, 3.0f, 2.7f};

struct SkyState {
    glm::vec3 sun_dir{0.4f, 0.8f, 0.3f};
    glm::vec3 sun_radiance = kClearSunRadiance;
    float sky_intensity = 1.0f;
    float overcast = 0.0f;  // 0 clear .. 1 a grey cloud deck hiding the sun
    bool operator==(const SkyState&) const = default;
};

// The sky under `weather` with the sun towards `sun_dir` (unit): cloud greys the sky and
// weakens the sun.
SkyState sky_under(const WeatherLook& weather, glm::vec3 sun_dir);

// The square the sun's shadow map covers: it follows the camera in steps (the debug
// panel's "shadow" group).
struct ShadowFraming {
    static constexpr float kCentreStep_m = 8.0f;  // the map follows the camera in steps of this
    float half_extent_m = 70.0f;
    float ahead_m = 30.0f;  // centre the map this far in front of the eye
};

// The sun's orthographic view-projection for a shadow map of `map_size` texels a side:
// centred `framing.ahead_m` in front of the eye on the ground at `ground_height_m`, in
// steps of kCentreStep_m, snapped to whole texels so that edges don't crawl.
glm::mat4 sun_shadow_view_proj(const Camera& camera, glm::vec3 sun_dir, float ground_height_m, int map_size,
                               const ShadowFraming& framing);

// Straight down over the props' bounds [lo, hi] (their square footprint, from above the
// highest): the sky-occlusion map's view-projection. The identity without props.
glm::mat4 sky_occlusion_view_proj(glm::vec3 props_min, glm::vec3 props_max);

// What that view takes in: a square of the xz plane, `half` metres either side of
// `centre` (x, z), looked at straight down from `top` through `depth_range` metres.
struct SkyOcclusionFraming {
    glm::vec2 centre{0.0f};
    float half = 0.0f, top = 0.0f, depth_range = 0.0f;
};
SkyOcclusionFraming sky_occlusion_framing(glm::vec3 props_min, glm::vec3 props_max);

struct FrameData {
    WeatherLook weather;                        // the road's wetness, the rain rate
    SkyState sky;                               // under that weather
    glm::mat4 sun_shadow_view_proj{1.0f};       // the shadow map's (ShadowPass draws it)
    glm::mat4 sky_occlusion_view_proj{1.0f};    // the sky-occlusion map's (SkyOcclusionPass)
    EnergyView energy;                          // the shots in flight: the energy glow
    std::vector<LineLight> line_lights;         // theirs (at most kMaxLineLights): every lit surface's
};

// What the frame's data is made from besides the world.
struct FrameSetting {
    const Camera& camera;
    glm::vec3 sun_dir;      // the level's, unit
    int shadow_map_size;    // texels a side
    ShadowFraming shadow_framing;
    glm::mat4 sky_occlusion_view_proj{1.0f};  // fixed for a level (the props stay put)
    BeamLighting beam_lighting{};             // the shots' line lights
    std::optional<WeatherLook> weather;       // instead of the world's
    std::optional<SkyState> sky;              // instead of the sky under the weather
    std::optional<EnergyView> energy;         // instead of the world's shots
};

// Fills `data` from the world. Reuses its storage.
void gather_frame_data(const sim::World& world, const FrameSetting& setting, FrameData& data);

}  // namespace effects
