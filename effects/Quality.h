#pragma once
// Quality presets: what each one changes in the frame. `auto` (game side) is medium with
// the render scale chosen every frame by the resolution controller.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace effects {

enum class Quality { Low, Medium, High };

struct QualitySettings {
    float render_scale = 1.0f;     // the 3D scene's size as a fraction of the output's
    int shadow_map_size = 1024;    // texels on a side
    int shadow_taps = 9;           // sun shadow filter: 1 (one bilinear compare) .. 9 (3x3 of them)
    bool env_reflection = true;    // opaque surfaces reflect the environment cube (else its ambient)
    bool ground_detail = true;     // the ground's fine noise octave
    int fluid_smoothing_max = 64;  // cap on the tank's depth smoothing iterations
    int fluid_kernel_max = 64;     // and on its kernel's width in pixels (odd)
    int rain_map_width = 1024;     // the windshield's drop height map (half as tall)
    bool bloom = true;             // the energy glow's bloom
    int dust_max_shells = 12;      // shells per dusty prop up close
    bool operator==(const QualitySettings&) const = default;
};

QualitySettings quality_settings(Quality quality);
std::string_view quality_name(Quality quality);
std::optional<Quality> parse_quality(std::string_view name);

// The #defines of shaders/common/lighting.glsl for these settings (SHADOW_TAPS,
// ENV_REFLECTION), for every program that includes it.
std::vector<std::string> lighting_defines(const QualitySettings& quality);

}  // namespace effects
