#include "effects/scene/SceneLighting.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec4.hpp>

namespace effects {

SceneLighting::SceneLighting(int env_size, int shadow_size, int sky_size)
    : env_levels_(gl::Texture::full_mip_levels(env_size, env_size)) {
    env_cube = gl::Texture::create_cube("sky.environment", GL_RGBA16F, env_size, env_levels_);
    env_cube.set_filter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    resize_shadow_map(shadow_size);
    sky_map = gl::Texture::create_2d("sky.occlusion_map", GL_DEPTH_COMPONENT32F, sky_size, sky_size);
    sky_map.set_filter(GL_LINEAR, GL_LINEAR);
    sky_map.set_wrap(GL_CLAMP_TO_EDGE);
    sky_map.set_depth_compare(true, GL_LEQUAL);
    const float far = 1.0f;
    glClearTexImage(sky_map.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &far);
    set_line_lights({});
}

void SceneLighting::resize_shadow_map(int size) {
    shadow_map = gl::Texture::create_2d("sun.shadow_map", GL_DEPTH_COMPONENT32F, size, size);
    shadow_map.set_filter(GL_LINEAR, GL_LINEAR);
    shadow_map.set_wrap(GL_CLAMP_TO_EDGE);
    shadow_map.set_depth_compare(true, GL_LEQUAL);
}

void SceneLighting::set_line_lights(std::span<const LineLight> lights) {
    // std140: the count, then starts, ends and colours of kMaxLineLights lights.
    std::vector<glm::vec4> block(1 + 3 * kMaxLineLights, glm::vec4(0.0f));
    const size_t n = std::min(lights.size(), kMaxLineLights);
    for (size_t i = 0; i < n; ++i) {
        block[1 + i] = glm::vec4(lights[i].start, lights[i].reach_m);
        block[1 + kMaxLineLights + i] = glm::vec4(lights[i].end, lights[i].intensity);
        block[1 + 2 * kMaxLineLights + i] = glm::vec4(lights[i].colour, 0.0f);
    }
    const int count = int(n);
    std::span<const std::byte> bytes = std::as_bytes(std::span(block));
    if (line_lights_.id() == 0)
        line_lights_ = gl::Buffer::create("lighting.line_lights", GLsizeiptr(bytes.size()), bytes.data());
    else
        line_lights_.update(0, bytes);
    line_lights_.update(0, std::as_bytes(std::span(&count, 1)));  // the ivec4 count's x, as an int
}

glm::vec3 SceneLighting::cabin_daylight(const SkyState& sky) {
    // The sky as common/sky.glsl has it, halfway up from the horizon (where the glass
    // is): blue when clear, the cloud deck's grey under cloud.
    const glm::vec3 clear_sky(0.30f, 0.44f, 0.70f), cloud(0.34f, 0.36f, 0.38f);
    const glm::vec3 sky_light = glm::mix(clear_sky, cloud, sky.overcast) * sky.sky_intensity;
    // A bounce off grey seats and a grey floor greys it too.
    const float grey = 0.2126f * sky_light.x + 0.7152f * sky_light.y + 0.0722f * sky_light.z;
    const glm::vec3 bounced_sky = glm::mix(glm::vec3(grey), sky_light, 0.25f);
    // The roof keeps a high sun out: what comes in goes with the cosine of its height.
    const float low_sun = std::sqrt(std::max(0.0f, 1.0f - sky.sun_dir.y * sky.sun_dir.y));
    constexpr float kSkyThroughGlass = 0.30f, kSunThroughGlass = 0.03f;
    return kSkyThroughGlass * bounced_sky + kSunThroughGlass * low_sun * sky.sun_radiance;
}

void SceneLighting::apply_sky(const gl::Program& p, const SkyState& sky) {
    p.set("u_sun_dir", sky.sun_dir);
    p.set("u_sun_radiance", sky.sun_radiance);
    p.set("u_sky_intensity", sky.sky_intensity);
    p.set("u_overcast", sky.overcast);
}

void SceneLighting::apply(const gl::Program& p, const FrameData& frame) const {
    apply_sky(p, frame.sky);
    // Texture coordinates in [0,1] and depth in [0,1] from clip space.
    glm::mat4 bias(0.5f);
    bias[3] = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    p.set("u_shadow_matrix", bias * frame.sun_shadow_view_proj);
    p.set("u_env_max_lod", env_max_lod());
    p.set("u_env", int(kEnvUnit));
    p.set("u_shadow_map", int(kShadowUnit));
    p.set("u_sky_matrix", bias * frame.sky_occlusion_view_proj);
    p.set("u_sky_map", int(kSkyUnit));
    p.set("u_cabin_daylight", cabin_daylight(frame.sky));
    env_cube.bind(kEnvUnit);
    shadow_map.bind(kShadowUnit);
    sky_map.bind(kSkyUnit);
    glBindBufferBase(GL_UNIFORM_BUFFER, kLineLightBinding, line_lights_.id());
}

}  // namespace effects
