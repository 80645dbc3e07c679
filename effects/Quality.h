#pragma once
// Quality presets: what each one changes in the frame. `auto` (game side) is medium with
// the render scale chosen every frame by the resolution controller.
#include <optional>
#include <string_view>

namespace effects {

enum class Quality { Low, Medium, High };

struct QualitySettings {
    float render_scale = 1.0f;     // the 3D scene's size as a fraction of the output's
    int shadow_map_size = 1024;    // texels on a side
    int shadow_taps = 9;           // sun shadow filter: 1 (one bilinear compare) .. 9 (3x3 of them)
    int fluid_smoothing_max = 64;  // cap on the tank's depth smoothing iterations
    bool bloom = true;             // the energy glow's bloom
    int dust_max_shells = 12;      // shells per dusty prop up close
};

QualitySettings quality_settings(Quality quality);
std::string_view quality_name(Quality quality);
std::optional<Quality> parse_quality(std::string_view name);

}  // namespace effects
