#version 450 core
#include "fluid/filter.glsl"
// The seed's baseline (eq. 3.1): a bilateral filter over the window, spatial sigma
// w / (2 sqrt 2) pixels, depth sigma 2 sqrt 2 r; pixels without liquid weigh nothing.
uniform float u_sigma_space;  // pixels
uniform float u_sigma_depth;  // view units

void main() {
    ivec2 pix;
    float z;
    if (!start_filter(pix, z)) return;
    float ks = 0.5 / (u_sigma_space * u_sigma_space), kd = 0.5 / (u_sigma_depth * u_sigma_depth);
    float sum = 0.0, wsum = 0.0;
    for (int j = -u_half; j <= u_half; ++j)
        for (int i = -u_half; i <= u_half; ++i) {
            float zq = texelFetch(u_depth, clamp_to_rect(pix + ivec2(i, j)), 0).r;
            if (!has_depth(zq)) continue;
            float w = exp(-float(i * i + j * j) * ks - (zq - z) * (zq - z) * kd);
            sum += w * zq;
            wsum += w;
        }
    o_depth = sum / wsum;
}
