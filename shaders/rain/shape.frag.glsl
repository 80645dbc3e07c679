#version 450 core
// From summed densities to the drops' surface (seed 5.2-5.4): the part above the
// threshold, compressed in steps so merged drops do not spike, turned into a height
// by the profile of a 3D metaball (so a lone drop is the hemisphere the seed's 3D
// reference gives, not the seed's flatter N - T) scaled by the local drop radius, and
// the normal from the right and upper neighbours.
uniform sampler2D u_density;  // r: sum N, g: sum N * radius (mm)
uniform vec2 u_texel_mm;
uniform float u_threshold;
uniform float u_first_level, u_level_step, u_k;
uniform int u_steps;
layout(location = 0) out vec4 o_surface;  // normal u, v; height mm; water

// Height in drop radii of a texel of (compressed) density n. Below 1 a lone drop's
// 2D density N = 1 / (1 + x^4) gives its distance x from the centre, and the 3D
// metaball of the same kernel stands there at sqrt(q - x^2), q = sqrt(1/T - 1): the
// hemisphere. Above 1 (merged drops, after the compression) the height rises on
// linearly; the slope is the one that best matches the 3D reference on the merged-drop
// scene (MetaballReference), checked by tests/rain_render_test.cpp.
const float kMergedSlope = 2.0;
float profile(float n) {
    float q = sqrt(1.0 / u_threshold - 1.0);
    if (n <= 1.0) return sqrt(max(q - sqrt(max(1.0 / n - 1.0, 0.0)), 0.0)) / sqrt(q);
    return 1.0 + kMergedSlope * (n - 1.0);
}

float height_mm(ivec2 p) {
    vec2 d = texelFetch(u_density, clamp(p, ivec2(0), textureSize(u_density, 0) - 1), 0).rg;
    float v = d.r - u_threshold;
    if (v <= 0.0) return 0.0;
    for (int i = 0; i < u_steps; ++i) {
        float v0 = u_first_level + u_level_step * float(i);
        if (v > v0) v = u_k * (v - v0) + v0;
    }
    return profile(v + u_threshold) * (d.g / d.r);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float h = height_mm(p);
    if (h <= 0.0) {
        o_surface = vec4(0.0);
        return;
    }
    float hu = height_mm(p + ivec2(1, 0)), hv = height_mm(p + ivec2(0, 1));
    // Tangents (dx, 0, dh_u) and (0, dy, dh_v); their cross product is the normal.
    vec3 n = normalize(vec3(-(hu - h) * u_texel_mm.y, -(hv - h) * u_texel_mm.x, u_texel_mm.x * u_texel_mm.y));
    o_surface = vec4(n.xy, h, 1.0);
}
