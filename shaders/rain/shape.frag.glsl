#version 450 core
// From the splatted sums to the drops' surface (seed 5.2-5.4; DropHeightMap.h). A
// texel is taken as one 3D metaball: the drop that dominates it (radius R, squared
// distance a in radii, both N^2-weighted means), with the strength s that gives the
// summed density n = s / (1 + a^2). That ball's field s / (1 + (a + z^2)^2) falls to
// T at the height z = sqrt(sqrt(s / T - 1) - a) radii: a lone drop's hemisphere, and
// exact where two equal drops meet. Normals from the right and upper neighbours.
uniform sampler2D u_sums;  // N, N^2 R (mm), N^2 x^2, N^2
uniform vec2 u_texel_mm;
uniform float u_threshold;
uniform float u_first_level, u_level_step, u_k;
uniform int u_steps;  // the seed's compression of n - T; 0 by default
layout(location = 0) out vec4 o_surface;  // normal u, v; height mm; water

float height_mm(ivec2 p) {
    vec4 s = texelFetch(u_sums, clamp(p, ivec2(0), textureSize(u_sums, 0) - 1), 0);
    float v = s.r - u_threshold;
    if (v <= 0.0 || s.a <= 0.0) return 0.0;
    for (int i = 0; i < u_steps; ++i) {
        float v0 = u_first_level + u_level_step * float(i);
        if (v > v0) v = u_k * (v - v0) + v0;
    }
    float a = s.b / s.a, radius_mm = s.g / s.a;
    float strength = (v + u_threshold) * (1.0 + a * a);
    return radius_mm * sqrt(max(sqrt(max(strength / u_threshold - 1.0, 0.0)) - a, 0.0));
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
