#version 450 core
#include "common/sky.glsl"
#include "common/lighting.glsl"
#include "water/shading.glsl"
#include "water/waves.glsl"
// Shades each sea pixel once (WaterShading): the geometry step left its depth, its
// normal and its kind; the depth test against the water mask leaves only sea (and
// sheet) pixels. Splash sheets have their own pass (shade_sheet.frag.glsl):
// a software rasteriser would run both kinds' code for every pixel of one shader.
uniform sampler2D u_depth;    // the scene's depth, water included
uniform sampler2D u_normals;  // the scene's normals, water included
uniform sampler2D u_kind;     // r: 0 none, 0.5 sea, 0.76..1 sheet; g: foam; b: how stirred
uniform float u_shore_foam;
layout(location = 0) out vec4 o_colour;

vec3 shade_sea(vec3 pos, vec3 n, vec3 v, float sun, float crest, float stirred) {
    float fresnel = water_fresnel(dot(n, v));
    vec3 reflection = water_reflection(n, v, sun, 0.08);
    float path;
    vec3 refraction = water_refraction(n, pos, path);
    vec3 c = mix(refraction, reflection, fresnel) + water_line_light(pos, n, fresnel);
    // Stirred water (a wake) is full of fine bubbles: it sends light back paler and
    // greener than the clear sea beside it, so the wake's wedge shows from any height.
    c = mix(c, foam_radiance(n, sun) * kWaterScatterAlbedo * 1.6, 0.45 * stirred);
    // Foam on crests and in shallow water, broken up by noise that drifts slowly so it
    // reads as patches, not paint. Most of the sea has none: skip the noise there.
    float shallow = u_shore_foam * (1.0 - smoothstep(0.05, 0.35, path));
    if (crest * u_foam + shallow > 0.0) {
        float breakup = foam_noise(pos.xz * 2.3 + u_time_s * 0.15) * 0.6 + foam_noise(pos.xz * 7.1) * 0.4;
        float foam = u_foam * crest * smoothstep(0.35, 0.8, breakup) + shallow * smoothstep(0.25, 0.6, breakup);
        c = mix(c, foam_radiance(n, sun), clamp(foam, 0.0, 1.0));
    }
    return c;
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 kind = texelFetch(u_kind, px, 0).rgb;
    if (kind.r < 0.25 || kind.r > 0.7) discard;
    vec3 pos = world_from_depth(gl_FragCoord.xy * u_inv_viewport, texelFetch(u_depth, px, 0).r);
    vec3 n = texelFetch(u_normals, px, 0).xyz;
    n = dot(n, n) > 1e-8 ? normalize(n) : vec3(0, 1, 0);
    vec3 v = normalize(u_eye - pos);
    vec3 c = shade_sea(pos, n, v, water_sun_visibility(pos), kind.g, kind.b);
    o_colour = vec4(apply_fog(c, pos, u_eye), 1.0);
}
