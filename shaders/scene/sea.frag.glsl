#version 450 core
#include "common/sky.glsl"
#include "common/lighting.glsl"
// The open sea at rest (the wave grid effect replaces it): small procedural ripples,
// Fresnel reflection of the sky, refraction of what lies below, absorbed with depth.
in vec3 v_world_pos;
uniform vec3 u_eye;
uniform float u_time_s;
uniform sampler2D u_scene_colour;  // copy of the opaque scene
uniform sampler2D u_scene_depth;
uniform vec2 u_inv_viewport;
uniform mat4 u_inv_proj;
uniform mat4 u_view;
layout(location = 0) out vec4 o_colour;
layout(location = 1) out vec4 o_normal;

float view_depth(vec2 uv, float d) {
    vec4 p = u_inv_proj * vec4(uv * 2.0 - 1.0, d * 2.0 - 1.0, 1.0);
    return -p.z / p.w;
}

vec2 ripple_slope(vec2 p, float t) {
    vec2 s = vec2(0.0);
    const vec3 waves[4] = vec3[](vec3(0.9, 0.3, 0.35), vec3(-0.4, 0.9, 0.55), vec3(0.2, -1.0, 0.9), vec3(-0.8, -0.5, 1.6));
    for (int i = 0; i < 4; ++i) {
        vec2 dir = normalize(waves[i].xy);
        float k = waves[i].z;
        float amp = 0.012 / k;
        float phase = dot(dir, p) * k * 2.0 - t * sqrt(9.81 * k * 2.0);
        s += dir * (amp * k * 2.0 * cos(phase));
    }
    return s;
}

void main() {
    // Ripples fade with distance: finer than a pixel they would only alias.
    float dist = length(u_eye - v_world_pos);
    vec2 slope = ripple_slope(v_world_pos.xz, u_time_s) * exp(-dist / 60.0);
    vec3 n = normalize(vec3(-slope.x, 1.0, -slope.y));
    vec3 v = normalize(u_eye - v_world_pos);
    float cos_v = max(dot(n, v), 0.0);
    float fresnel = 0.02 + 0.98 * pow(1.0 - cos_v, 5.0);

    vec3 r = reflect(-v, n);
    r.y = abs(r.y);
    vec3 reflection = textureLod(u_env, r, 0.0).rgb;
    float shadow = sun_visibility(v_world_pos, vec3(0, 1, 0));
    reflection += u_sun_radiance * ggx_specular(n, v, u_sun_dir, 0.08) * shadow;

    vec2 uv = gl_FragCoord.xy * u_inv_viewport;
    vec2 refr_uv = clamp(uv + n.xz * 0.03, vec2(0.001), vec2(0.999));
    float surface = view_depth(uv, gl_FragCoord.z);
    float below = view_depth(refr_uv, texture(u_scene_depth, refr_uv).r);
    if (below < surface) {  // the offset sample is in front of the water: don't refract it
        refr_uv = uv;
        below = view_depth(uv, texture(u_scene_depth, uv).r);
    }
    float path = max(below - surface, 0.0);
    vec3 deep = vec3(0.004, 0.03, 0.045) * u_sky_intensity;
    vec3 absorb = exp(-path * vec3(0.45, 0.12, 0.09));
    vec3 refraction = mix(deep, texture(u_scene_colour, refr_uv).rgb, absorb);

    vec3 c = mix(refraction, reflection, fresnel);
    o_colour = vec4(apply_fog(c, v_world_pos, u_eye), 1.0);
    o_normal = vec4(n, 1.0);
}
