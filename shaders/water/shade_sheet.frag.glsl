#version 450 core
#include "common/sky.glsl"
#include "common/lighting.glsl"
#include "water/shading.glsl"
// Shades each splash-sheet pixel once (WaterShading): a thin film that reflects like
// the sea, lets through most of what is behind it and whitens where it is torn. The
// depth test against the water mask leaves only sheet pixels.
uniform sampler2D u_depth;    // the scene's depth, water included
uniform sampler2D u_normals;  // the scene's normals, water included
uniform sampler2D u_kind;     // r: 0.76..1 on a sheet (its thickness); g: foam; b: opacity
uniform float u_sheet_thickness_m;  // at rest
layout(location = 0) out vec4 o_colour;

// Behind a splash sheet. The scene copy has no water in it: where the ray behind the
// sheet reaches below the sea level, shade the flat sea it crosses instead.
vec3 sheet_background(vec3 n) {
    vec2 uv = gl_FragCoord.xy * u_inv_viewport;
    vec2 refr_uv = clamp(uv + n.xz * u_refraction * 0.5, vec2(0.001), vec2(0.999));
    vec3 behind = world_from_depth(refr_uv, texture(u_scene_depth, refr_uv).r);
    vec3 scene = texture(u_scene_colour, refr_uv).rgb;
    vec3 d = behind - u_eye;
    if (u_eye.y <= u_sea_level || behind.y >= u_sea_level || d.y >= 0.0) return scene;
    float t = (u_sea_level - u_eye.y) / d.y;  // fraction of the way to `behind` where it meets the sea
    vec3 at_sea = u_eye + d * t;
    float path = length(d) * (1.0 - t);
    vec3 below = mix(deep_water_colour(), scene, exp(-path * kAbsorbPerMetre * u_absorption));
    vec3 v = normalize(u_eye - at_sea);
    vec3 r = reflect(-v, vec3(0, 1, 0));
    return mix(below, textureLod(u_env, r, 0.0).rgb, water_fresnel(v.y));
}

vec3 shade_sheet(vec3 pos, vec3 n, vec3 v, float sun, float thickness_m, float whiteness) {
    float cos_v = max(dot(n, v), 0.0);
    vec3 reflection = water_reflection(n, v, sun, 0.12);
    // Light crosses the film obliquely: the path grows as 1/cos.
    float path = thickness_m / max(cos_v, 0.05);
    vec3 transmitted = sheet_background(n) * exp(-path * kAbsorbPerMetre * u_absorption * 8.0);
    vec3 c = mix(transmitted, reflection, water_fresnel(cos_v));
    return mix(c, foam_radiance(n, sun), whiteness);
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 kind = texelFetch(u_kind, px, 0).rgb;
    vec3 pos = world_from_depth(gl_FragCoord.xy * u_inv_viewport, texelFetch(u_depth, px, 0).r);
    vec3 n = texelFetch(u_normals, px, 0).xyz;
    n = dot(n, n) > 1e-8 ? normalize(n) : vec3(0, 1, 0);
    vec3 v = normalize(u_eye - pos);
    float thickness = u_sheet_thickness_m * clamp((kind.r - 0.76) / 0.24, 0.0, 1.0);
    vec3 c = shade_sheet(pos, n, v, water_sun_visibility(pos), thickness, kind.g);
    c = mix(sheet_background(vec3(0, 1, 0)), c, kind.b);  // what lies behind shows through its edges
    o_colour = vec4(apply_fog(c, pos, u_eye), 1.0);
}
