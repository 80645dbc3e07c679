// Shared by the body's depth filters (plane_fit, bilateral, narrow_range .frag.glsl):
// the depth map they smooth, the window's half width, and the smoothed depth they write.
#include "fluid/common.glsl"
uniform sampler2D u_depth;
uniform int u_half;          // kernel half width: (K - 1) / 2
layout(location = 0) out float o_depth;

// The pixel and its depth, which is also written as the result: a pixel the filter
// leaves keeps its depth. False where the pixel has no liquid: nothing to filter.
bool start_filter(out ivec2 pix, out float z) {
    pix = ivec2(gl_FragCoord.xy);
    z = texelFetch(u_depth, pix, 0).r;
    o_depth = z;
    return has_depth(z);
}
