#version 450 core
// Adds the drop's density N(h) = 1 / (1 + (h/R)^4) and, weighted by N^2 so the nearest
// drop dominates, its radius and the texel's squared distance from its centre in radii
// (the shape pass makes one metaball of them). The kernel is computed, not read from a
// profile texture: on llvmpipe a fetch costs more than the arithmetic.
uniform float u_reach;
in vec2 v_offset;
flat in float v_radius_mm;
layout(location = 0) out vec4 o_sums;  // N, N^2 R (mm), N^2 x^2, N^2
void main() {
    float x2 = dot(v_offset, v_offset);
    if (x2 >= u_reach * u_reach) discard;
    float n = 1.0 / (1.0 + x2 * x2);
    float w = n * n;
    o_sums = vec4(n, w * v_radius_mm, w * x2, w);
}
