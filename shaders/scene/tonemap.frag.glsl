#version 450 core
// HDR scene to display: exposure, ACES filmic fit, sRGB encoding (common/tonemap.glsl).
#include "common/tonemap.glsl"
uniform sampler2D u_hdr;
uniform float u_exposure;
layout(location = 0) out vec4 o_colour;

void main() {
    // Drawn at the scene's own size (TonemapPass): one texel a pixel, unfiltered.
    vec3 hdr = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb * u_exposure;
    o_colour = vec4(tonemap(hdr), 1.0);
}
