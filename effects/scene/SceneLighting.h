#pragma once
// Sun, sky and their textures: the environment cube the sky fills and the sun's
// shadow map. Every lit pass binds them with apply().
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"

namespace effects {

struct SkyState {
    glm::vec3 sun_dir{0.4f, 0.8f, 0.3f};
    glm::vec3 sun_radiance{3.2f, 3.0f, 2.7f};
    float sky_intensity = 1.0f;
    bool operator==(const SkyState&) const = default;
};

class SceneLighting {
public:
    static constexpr GLuint kEnvUnit = 14;
    static constexpr GLuint kShadowUnit = 15;

    SceneLighting(int env_size, int shadow_size);

    // Sky uniforms only (sky background, environment faces).
    void apply_sky(const gl::Program& program) const;
    // Everything a lit surface needs.
    void apply(const gl::Program& program) const;

    SkyState sky;
    glm::mat4 shadow_view_proj{1.0f};
    gl::Texture env_cube;
    gl::Texture shadow_map;
    float env_max_lod() const { return float(env_levels_ - 1); }

private:
    int env_levels_;
};

}  // namespace effects
