#pragma once
// The lighting's textures: the environment cube the sky fills, the sun's shadow map, the
// sky-occlusion map and the line lights. Every lit pass binds them, with the frame's sky
// and matrices (FrameData), through apply().
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "effects/gl/Buffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/scene/FrameData.h"
#include "effects/scene/LineLight.h"

namespace effects {

// The sky-occlusion map's texels a side (SkyOcclusionPass draws the props into it).
inline constexpr int kSkyMapSize = 1024;

class SceneLighting {
public:
    static constexpr GLuint kEnvUnit = 14;
    static constexpr GLuint kShadowUnit = 15;
    static constexpr GLuint kSkyUnit = 13;
    static constexpr GLuint kLineLightBinding = 3;

    SceneLighting(int env_size, int shadow_size, int sky_size = kSkyMapSize);

    // Sky uniforms only (sky background, environment faces).
    static void apply_sky(const gl::Program& program, const SkyState& sky);
    // Everything a lit surface needs: the frame's sky and the maps' matrices with the
    // textures they belong to.
    void apply(const gl::Program& program, const FrameData& frame) const;

    gl::Texture env_cube;
    gl::Texture shadow_map;  // from FrameData::sun_shadow_view_proj
    // Top-down depth of the props (SkyOcclusionPass), from FrameData::sky_occlusion_view_proj:
    // what lies under a roof sees no sky. Cleared to "nothing above" until the pass draws it.
    gl::Texture sky_map;
    float env_max_lod() const { return float(env_levels_ - 1); }
    // The irradiance in a car's cabin under its roof (over pi: a lining's albedo times it
    // is its radiance), which sees the sky and the sun only through the glass: the sky's
    // light that the windows let in and the sun's when it is low enough to come through
    // them, both passed on by the seats and the dashboard. Cloud darkens both.
    static glm::vec3 cabin_daylight(const SkyState& sky);
    // A new shadow map of `size` texels on a side (nothing drawn in it yet).
    void resize_shadow_map(int size);
    // Uploads the frame's line lights (FrameData::line_lights; beyond kMaxLineLights
    // ignored) for apply() to bind: the renderer does, once a frame before the passes.
    void set_line_lights(std::span<const LineLight> lights);

private:
    int env_levels_;
    gl::Buffer line_lights_;
};

}  // namespace effects
