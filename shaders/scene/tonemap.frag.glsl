#version 450 core
// HDR scene to display: exposure, ACES filmic fit (Narkowicz 2015), sRGB encoding.
uniform sampler2D u_hdr;
uniform float u_exposure;
layout(location = 0) out vec4 o_colour;

vec3 aces(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
vec3 srgb_encode(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}
void main() {
    // Drawn at the scene's own size (TonemapPass): one texel a pixel, unfiltered.
    vec3 hdr = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb * u_exposure;
    o_colour = vec4(srgb_encode(aces(hdr)), 1.0);
}
