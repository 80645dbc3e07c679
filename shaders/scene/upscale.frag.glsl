#version 450 core
// The tone-mapped frame from the scene's size to the output's: a bilinear upscale that
// turns steeper where the 2x2 texels around the pixel differ (edges stay crisp, smooth
// gradients stay smooth), then contrast-adaptive sharpening in the manner of AMD's CAS
// (more where the neighbourhood is soft, clamped to its range so nothing rings).
// Four texel fetches a pixel: on a CPU rasteriser each filtered fetch costs more than
// the arithmetic here.
in vec2 v_uv;
uniform sampler2D u_display;  // sRGB-encoded, at the scene's size
uniform float u_edge;         // 0: plain bilinear .. 1: edges three times steeper
uniform float u_sharpness;    // 0 .. 1
layout(location = 0) out vec4 o_colour;

float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }

void main() {
    const ivec2 last = textureSize(u_display, 0) - 1;
    const vec2 p = v_uv * vec2(last + 1) - 0.5;
    const ivec2 i = ivec2(floor(p));
    vec2 f = p - vec2(i);
    vec3 a = texelFetch(u_display, clamp(i, ivec2(0), last), 0).rgb;
    vec3 b = texelFetch(u_display, clamp(i + ivec2(1, 0), ivec2(0), last), 0).rgb;
    vec3 c = texelFetch(u_display, clamp(i + ivec2(0, 1), ivec2(0), last), 0).rgb;
    vec3 d = texelFetch(u_display, clamp(i + ivec2(1, 1), ivec2(0), last), 0).rgb;
    vec3 lo = min(min(a, b), min(c, d)), hi = max(max(a, b), max(c, d));

    float contrast = luma(hi) - luma(lo);
    float steep = 1.0 + 2.0 * u_edge * smoothstep(0.04, 0.25, contrast);
    f = clamp((f - 0.5) * steep + 0.5, 0.0, 1.0);
    vec3 colour = mix(mix(a, b, f.x), mix(c, d, f.x), f.y);

    vec3 amount = sqrt(clamp(min(lo, 1.0 - hi) / max(hi, vec3(1e-4)), 0.0, 1.0)) * u_sharpness;
    vec3 mean = 0.25 * (a + b + c + d);
    o_colour = vec4(clamp(colour + amount * (colour - mean), lo, hi), 1.0);
}
