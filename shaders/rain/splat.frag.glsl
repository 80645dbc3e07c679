#version 450 core
// Adds the drop's density N(h) = 1 / (1 + (h/R)^4), read from the precomputed profile,
// and the density times the drop's radius (for the height of merged drops).
uniform sampler2D u_profile;  // N over h/R in [0, reach]
uniform float u_reach;
in vec2 v_offset;
flat in float v_radius_mm;
layout(location = 0) out vec2 o_density;
void main() {
    float x = length(v_offset) / u_reach;
    if (x >= 1.0) discard;
    float n = texture(u_profile, vec2((x * 255.0 + 0.5) / 256.0, 0.5)).r;
    o_density = vec2(n, n * v_radius_mm);
}
