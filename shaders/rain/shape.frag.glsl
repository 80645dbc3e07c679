#version 450 core
// From summed densities to the drops' surface (seed 5.2-5.4): the part above the
// threshold, compressed in steps so merged drops do not spike, scaled to millimetres
// by the local drop radius, and the normal from the right and upper neighbours.
uniform sampler2D u_density;  // r: sum N, g: sum N * radius (mm)
uniform vec2 u_texel_mm;
uniform float u_threshold;
uniform float u_first_level, u_level_step, u_k;
uniform int u_steps;
layout(location = 0) out vec4 o_surface;  // normal u, v; height mm; water

float height_mm(ivec2 p) {
    vec2 d = texelFetch(u_density, clamp(p, ivec2(0), textureSize(u_density, 0) - 1), 0).rg;
    float v = d.r - u_threshold;
    if (v <= 0.0) return 0.0;
    for (int i = 0; i < u_steps; ++i) {
        float v0 = u_first_level + u_level_step * float(i);
        if (v > v0) v = u_k * (v - v0) + v0;
    }
    // A lone drop peaks at v = 1 - T = 0.5: as high as its radius.
    return v * (d.g / d.r) / (1.0 - u_threshold);
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
