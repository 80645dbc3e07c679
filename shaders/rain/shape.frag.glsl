#version 450 core
// From the splatted sums to the drops' heights (seed 5.2-5.3; DropHeightMap.h); the
// normals follow in normals.frag.glsl. A texel is taken as one 3D metaball: the drop
// that dominates it (radius R, squared distance a in radii, both N^2-weighted means),
// with the strength s that gives the summed density n = s / (1 + a^2). That ball's
// field s / (1 + (a + z^2)^2) falls to T at the height z = sqrt(sqrt(s / T - 1) - a)
// radii: a lone drop's hemisphere, and exact where two equal drops meet.
uniform sampler2D u_sums;  // N, N^2 R (mm), N^2 x^2, N^2
uniform float u_threshold;
uniform float u_first_level, u_level_step, u_k;
uniform int u_steps;  // the seed's compression of n - T; 0 by default
layout(location = 0) out float o_height_mm;  // 0: dry

void main() {
    vec4 s = texelFetch(u_sums, ivec2(gl_FragCoord.xy), 0);
    float v = s.r - u_threshold;
    if (v <= 0.0 || s.a <= 0.0) {
        o_height_mm = 0.0;
        return;
    }
    for (int i = 0; i < u_steps; ++i) {
        float v0 = u_first_level + u_level_step * float(i);
        if (v > v0) v = u_k * (v - v0) + v0;
    }
    float a = s.b / s.a, radius_mm = s.g / s.a;
    float strength = (v + u_threshold) * (1.0 + a * a);
    o_height_mm = radius_mm * sqrt(max(sqrt(max(strength / u_threshold - 1.0, 0.0)) - a, 0.0));
}
