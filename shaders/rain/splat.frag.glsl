#version 450 core
// Adds the drop's density N(h) = 1 / (1 + (h/R)^4), read from the precomputed profile,
// and, weighted by N^2 so the nearest drop dominates, its radius and the texel's
// squared distance from its centre in radii (the shape pass makes one metaball of them).
uniform sampler2D u_profile;  // N over h/R in [0, reach]
uniform float u_reach;
in vec2 v_offset;
flat in float v_radius_mm;
layout(location = 0) out vec4 o_sums;  // N, N^2 R (mm), N^2 x^2, N^2
void main() {
    float x2 = dot(v_offset, v_offset);
    if (x2 >= u_reach * u_reach) discard;
    float t = sqrt(x2) / u_reach;
    float n = texture(u_profile, vec2((t * 255.0 + 0.5) / 256.0, 0.5)).r;
    float w = n * n;
    o_sums = vec4(n, w * v_radius_mm, w * x2, w);
}
