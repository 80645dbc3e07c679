#version 450 core
#include "common/sky.glsl"
#include "fluid/common.glsl"
// The splash over the refracted liquid: a whitish, partly clear layer whose opacity
// follows the water it holds along the ray, 1 - exp(-k thickness), read bilinearly from
// the low-resolution thickness target. Lit by the sky from above and around, a little
// of the sun through it; premultiplied alpha.
uniform sampler2D u_thickness;
uniform float u_opacity_per_m;  // k
uniform mat3 u_view_to_world;
layout(location = 0) out vec4 o_colour;

void main() {
    float t = texture(u_thickness, gl_FragCoord.xy / u_viewport).r;
    float a = 1.0 - exp(-u_opacity_per_m * t);
    if (a < 0.004) discard;
    vec3 dir = u_view_to_world * normalize(view_ray(gl_FragCoord.xy));
    vec3 light = 0.55 * sky_radiance(vec3(0.0, 1.0, 0.0), false) + 0.35 * sky_radiance(dir, false) +
                 0.12 * u_sun_radiance;
    o_colour = vec4(light * vec3(0.92, 0.97, 0.98) * a, a);
}
