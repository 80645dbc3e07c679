#version 450 core
// The wave grid's slope (dh/dx, dh/dz) and Laplacian per cell, from central
// differences (one-sided on the border), for the sea's normals and its crest foam.
uniform sampler2D u_heights;  // R32F, texel (i, j) = height of cell (i, j)
uniform float u_spacing;
layout(location = 0) out vec4 o_slopes;

float h(ivec2 p) { return texelFetch(u_heights, p, 0).r; }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(u_heights, 0) - 1;
    ivec2 lo = max(p - 1, ivec2(0)), hi = min(p + 1, last);
    float hx0 = h(ivec2(lo.x, p.y)), hx1 = h(ivec2(hi.x, p.y));
    float hz0 = h(ivec2(p.x, lo.y)), hz1 = h(ivec2(p.x, hi.y));
    float centre = h(p);
    vec2 slope = vec2((hx1 - hx0) / max(float(hi.x - lo.x), 1.0), (hz1 - hz0) / max(float(hi.y - lo.y), 1.0)) / u_spacing;
    float laplacian = (hx0 + hx1 + hz0 + hz1 - 4.0 * centre) / (u_spacing * u_spacing);
    o_slopes = vec4(slope, laplacian, 0.0);
}
