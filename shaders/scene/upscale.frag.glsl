#version 450 core
// The display image from the scene's size to the output's: one bilinear fetch, taken
// where the pixel's place within its 2x2 texels is pushed towards the nearer texel
// (steeper ramps between texels, so the enlarged image is less soft; no overshoot, as
// it stays a bilinear mix). On llvmpipe each fetch at the output's size costs about a
// trivial fill, so this is the whole filter: what it enlarges is anti-aliased at the
// scene's size first (the temporal resolve), which is where the stairs are taken out.
in vec2 v_uv;
uniform sampler2D u_display;  // sRGB-encoded, at the scene's size, bilinear
uniform float u_edge;         // 0: plain bilinear .. 1: three times steeper
layout(location = 0) out vec4 o_colour;

void main() {
    const vec2 size = vec2(textureSize(u_display, 0));
    const vec2 p = v_uv * size - 0.5;
    const vec2 i = floor(p);
    const vec2 f = clamp((p - i - 0.5) * (1.0 + 2.0 * u_edge) + 0.5, 0.0, 1.0);
    o_colour = vec4(texture(u_display, (i + 0.5 + f) / size).rgb, 1.0);
}
