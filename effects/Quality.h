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
    bool soft_shadows = true;      // the sun's shadow filtered over 4x4 texels (else 2x2)
    bool env_reflection = true;    // opaque surfaces reflect the environment cube (else its ambient)
    bool ground_detail = true;     // the ground's fine noise octave
    int fluid_smoothing_max = 64;  // cap on the tank's depth smoothing iterations
    int fluid_kernel_max = 64;     // and on its kernel's width in pixels (odd)
    int rain_map_width = 768;      // the windshield's drop height map (half as tall)
    bool bloom = true;             // the energy glow's bloom
    int dust_max_shells = 12;      // shells per dusty prop up close
    int mirror_width = 160;        // the rear-view mirror's picture of the view behind, a
                                   // quarter as tall (0: the glass reflects the sky instead)
    // FXAA over the tone-mapped frame, off in every preset: on llvmpipe it costs about a
    // quarter of a high frame (docs/PERFORMANCE.md), so the player turns it on (F3).
    bool antialias = false;
    // Temporal upsampling (TemporalPass): the projection jittered by a sub-pixel offset
    // each frame and the tone-mapped frame resolved against the last one reprojected, so
    // a scene drawn small is anti-aliased before the upscale. No preset turns it on
    // (the goldens are single frames); the game does on `auto` (Renderer::set_temporal).
    bool temporal = false;
    bool operator==(const QualitySettings&) const = default;
};

QualitySettings quality_settings(Quality quality);
std::string_view quality_name(Quality quality);
std::optional<Quality> parse_quality(std::string_view name);

// The shaders' #defines for these settings (common/lighting.glsl's SOFT_SHADOWS and
// ENV_REFLECTION, scene/mesh.frag.glsl's GROUND_DETAIL) and for whether the frame has
// line lights (LINE_LIGHTS); effects/scene/LitProgram keeps the variants.
std::vector<std::string> shader_defines(const QualitySettings& quality, bool line_lights);

}  // namespace effects
