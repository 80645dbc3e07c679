#version 450 core
#include "rain/drop_shape.glsl"
// The drops' surface per texel of the height map, from the sums at the texel and its
// right and upper neighbours (clamped at the edges): what the windshield takes per
// pixel, at the texel centres. Made for the tests and the bench, not in the frame.
// Drawn over the wet tiles (tiles.vert.glsl); outside them the sums are the cleared 0.
uniform sampler2D u_sums;  // N, N^2 R (mm), N^2 x^2, N^2
uniform vec2 u_texel_mm;
layout(location = 0) out vec4 o_surface;  // normal u, v; height mm; water

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy), last = textureSize(u_sums, 0) - 1;
    o_surface = drop_surface(texelFetch(u_sums, p, 0), texelFetch(u_sums, min(p + ivec2(1, 0), last), 0),
                             texelFetch(u_sums, min(p + ivec2(0, 1), last), 0), u_texel_mm);
}
