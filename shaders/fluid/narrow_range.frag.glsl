#version 450 core
#include "fluid/filter.glsl"
// A narrow-range filter after Truong & Yuksel (2018): a Gaussian over the window that
// only averages depths within a narrow band around the pixel's: samples far behind it
// are ignored, samples far in front are clamped to the band's near edge, so edges
// neither blur into the background nor bend towards the viewer.
uniform float u_sigma_space;  // pixels
uniform float u_band;         // view units

void main() {
    ivec2 pix;
    float z;
    if (!start_filter(pix, z)) return;
    float ks = 0.5 / (u_sigma_space * u_sigma_space);
    float sum = 0.0, wsum = 0.0;
    for (int j = -u_half; j <= u_half; ++j)
        for (int i = -u_half; i <= u_half; ++i) {
            float zq = texelFetch(u_depth, clamp_to_rect(pix + ivec2(i, j)), 0).r;
            if (!has_depth(zq) || zq > z + u_band) continue;
            zq = max(zq, z - u_band);
            float w = exp(-float(i * i + j * j) * ks);
            sum += w * zq;
            wsum += w;
        }
    o_depth = sum / wsum;
}
