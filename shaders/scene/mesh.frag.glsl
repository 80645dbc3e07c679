#version 450 core
#include "common/sky.glsl"
#include "common/lighting.glsl"

in vec3 v_world_pos;
in vec3 v_normal;
in vec4 v_color;

uniform vec3 u_eye;
uniform vec4 u_tint;  // multiplies the vertex colour (thrown objects' colours)
uniform float u_roughness;
uniform float u_metallic;
uniform vec3 u_emissive;  // the material's own light (a lamp, the speedometer's needle)
// The car's cabin lining (SceneGeometry: 1 for its meshes, else 0) sees the sky only
// through the glass: the roof's shadow and the sky occlusion would leave it black, so it
// takes the daylight the glass lets in (SceneLighting::cabin_daylight) instead.
uniform float u_cabin_lining;
uniform vec3 u_cabin_daylight;

// GROUND (a variant of the program): the terrain, coloured here as roads (rectangles
// in xz, ROAD_COUNT of them), grass, the quay's concrete and the sea bed; otherwise the
// vertex colour.
#ifndef ROAD_COUNT
#define ROAD_COUNT 0
#endif
uniform vec4 u_roads[16];  // min.xz, max.xz
uniform float u_shore_z;
uniform float u_sea_level;
uniform float u_wetness;  // the road's wetness from the sim's weather: 0 dry .. 1 running with water

layout(location = 0) out vec4 o_colour;
#ifdef SCENE_NORMALS  // only when SceneTargets draws them (an EXR capture, a test)
layout(location = 1) out vec4 o_normal;
#endif

float hash12(vec2 p) {
    vec3 p3 = fract(vec3(p.xyx) * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}

float value_noise(vec2 p) {
    vec2 i = floor(p), f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash12(i), hash12(i + vec2(1, 0)), u.x), mix(hash12(i + vec2(0, 1)), hash12(i + vec2(1, 1)), u.x), u.y);
}

// `wet_roughness`: the roughness when soaked. Water fills a surface's pores: asphalt and
// concrete turn nearly mirror-like and reflect the sky, grass only a little glossier.
vec3 ground_colour(vec3 p, out float roughness, out float wet_roughness) {
    // GROUND_DETAIL 0 (a cheaper preset's): the coarse octave alone.
#if defined(GROUND_DETAIL) && GROUND_DETAIL == 0
    float n = value_noise(p.xz * 0.35) * 0.6 + 0.2;
#else
    float n = value_noise(p.xz * 0.35) * 0.6 + value_noise(p.xz * 2.1) * 0.4;
#endif
    vec3 grass = mix(vec3(0.10, 0.17, 0.05), vec3(0.16, 0.22, 0.07), n);
    vec3 c = grass;
    roughness = 0.95;
    wet_roughness = 0.6;
    if (p.z > u_shore_z - 3.0) {  // the quay: concrete slabs
        float joints = step(0.96, fract(p.x / 4.0)) + step(0.93, fract((p.z - u_shore_z) / 3.0));
        c = mix(vec3(0.30, 0.29, 0.27), vec3(0.36, 0.35, 0.33), n) * (1.0 - 0.35 * min(joints, 1.0));
        roughness = 0.85;
        wet_roughness = 0.3 - 0.15 * n;
    }
    if (p.y < u_sea_level - 0.3) {  // below the quay: weedy stone and sand
        c = mix(vec3(0.10, 0.11, 0.08), vec3(0.28, 0.25, 0.18), smoothstep(-2.0, -5.0, p.y)) * (0.8 + 0.4 * n);
        roughness = 0.9;
        wet_roughness = 0.9;
    }
    for (int i = 0; i < ROAD_COUNT; ++i) {
        vec4 r = u_roads[i];
        if (p.x >= r.x && p.x <= r.z && p.z >= r.y && p.z <= r.w) {
            c = vec3(0.045, 0.045, 0.05) * (0.85 + 0.3 * n);
            roughness = 0.7;
            // The worn hollows (the noise's high end) hold puddles: mirrors of the sky.
            wet_roughness = mix(0.2, 0.03, smoothstep(0.5, 0.7, n));
            // Dashed centre line along the road's long axis.
            bool along_x = (r.z - r.x) > (r.w - r.y);
            float centre = along_x ? abs(p.z - 0.5 * (r.y + r.w)) : abs(p.x - 0.5 * (r.x + r.z));
            float dash = along_x ? fract(p.x / 6.0) : fract(p.z / 6.0);
            if (centre < 0.08 && dash < 0.5) c = vec3(0.55, 0.52, 0.40);
        }
    }
    return c;
}

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;
    vec3 base = v_color.rgb * u_tint.rgb;
    float roughness = u_roughness;
#ifdef GROUND
    float wet_roughness;
    base = ground_colour(v_world_pos, roughness, wet_roughness);
    // Wet: darker (the water film lets less light scatter back out) and glossier.
    base *= 1.0 - 0.5 * u_wetness;
    roughness = mix(roughness, wet_roughness, u_wetness);
#endif
    vec3 c = shade_surface(base, roughness, u_metallic, v_world_pos, n, u_eye) + u_emissive +
             base * (1.0 - u_metallic) * (u_cabin_lining * u_cabin_daylight);
    o_colour = vec4(apply_fog(c, v_world_pos, u_eye), 1.0);
#ifdef SCENE_NORMALS
    o_normal = vec4(n, 1.0);
#endif
}
