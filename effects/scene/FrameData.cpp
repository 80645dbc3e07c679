#include "effects/scene/FrameData.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace effects {

SkyState sky_under(const WeatherLook& weather, glm::vec3 sun_dir) {
    SkyState sky;
    sky.sun_dir = sun_dir;
    sky.sun_radiance = kClearSunRadiance * weather.sunlight;
    sky.sky_intensity = weather.sky_intensity;
    sky.overcast = weather.overcast;
    return sky;
}

glm::mat4 sun_shadow_view_proj(const Camera& camera, glm::vec3 sun_dir, float ground_height_m, int map_size,
                               const ShadowFraming& framing) {
    glm::vec3 view_dir = -glm::vec3(camera.view[0][2], camera.view[1][2], camera.view[2][2]);
    glm::vec3 flat(view_dir.x, 0.0f, view_dir.z);
    float len = std::sqrt(flat.x * flat.x + flat.z * flat.z);
    glm::vec3 centre = camera.eye + (len > 1e-3f ? flat / len : glm::vec3(0.0f)) * framing.ahead_m;
    centre.y = ground_height_m;
    // In steps, so that the shadow pass's map of what stays put is drawn again only when
    // a step is taken.
    centre.x = std::round(centre.x / ShadowFraming::kCentreStep_m) * ShadowFraming::kCentreStep_m;
    centre.z = std::round(centre.z / ShadowFraming::kCentreStep_m) * ShadowFraming::kCentreStep_m;

    glm::vec3 up = std::fabs(sun_dir.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    glm::mat4 view = glm::lookAt(centre + sun_dir * 200.0f, centre, up);
    // Snap the centre to whole texels in light space.
    const float half = framing.half_extent_m;
    float texel = 2.0f * half / float(map_size);
    glm::vec4 origin = view * glm::vec4(0, 0, 0, 1);
    glm::vec2 snap(std::round(origin.x / texel) * texel - origin.x, std::round(origin.y / texel) * texel - origin.y);
    view = glm::translate(glm::mat4(1.0f), glm::vec3(snap, 0.0f)) * view;
    glm::mat4 proj = glm::ortho(-half, half, -half, half, 1.0f, 420.0f);
    return proj * view;
}

SkyOcclusionFraming sky_occlusion_framing(glm::vec3 lo, glm::vec3 hi) {
    // Looking straight down from above the highest prop over their square footprint.
    SkyOcclusionFraming f;
    f.centre = glm::vec2(0.5f * (lo.x + hi.x), 0.5f * (lo.z + hi.z));
    f.half = 0.5f * std::max(hi.x - lo.x, hi.z - lo.z) + 1.0f;
    f.top = hi.y + 1.0f;
    f.depth_range = f.top - lo.y + 1.0f;
    return f;
}

glm::mat4 sky_occlusion_view_proj(glm::vec3 lo, glm::vec3 hi) {
    if (!(hi.x > lo.x && hi.z > lo.z)) return glm::mat4(1.0f);  // no props: nothing above anything
    const SkyOcclusionFraming f = sky_occlusion_framing(lo, hi);
    const glm::mat4 view = glm::lookAt(glm::vec3(f.centre.x, f.top, f.centre.y),
                                       glm::vec3(f.centre.x, f.top - 1.0f, f.centre.y), glm::vec3(0, 0, -1));
    const glm::mat4 proj = glm::ortho(-f.half, f.half, -f.half, f.half, 0.0f, f.depth_range);
    return proj * view;
}

void gather_frame_data(const sim::World& world, const FrameSetting& setting, FrameData& data) {
    data.weather = setting.weather ? *setting.weather : weather_look(world);
    data.sky = setting.sky ? *setting.sky : sky_under(data.weather, setting.sun_dir);
    data.sun_shadow_view_proj = sun_shadow_view_proj(setting.camera, data.sky.sun_dir, world.level().land_height_m,
                                                     setting.shadow_map_size, setting.shadow_framing);
    data.sky_occlusion_view_proj = setting.sky_occlusion_view_proj;
    if (setting.energy) data.energy = *setting.energy;
    else gather_energy_view(world, data.energy);
    beam_line_lights(data.energy, setting.beam_lighting, data.line_lights);
}

}  // namespace effects
