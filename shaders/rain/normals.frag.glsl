#version 450 core
// Normals of a height map (seed 5.4), from the right and upper neighbours; shared by
// the 2D path (shape.frag.glsl's heights) and the 3D reference (reference.frag.glsl's).
// One gather at the texel's upper-right corner brings the texel and both neighbours
// (clamped at the edges): under llvmpipe each fetch of a per-texel pass costs about
// as much as the rest of the pass, and a gather costs one. Drawn over the wet tiles
// (tiles.vert.glsl); a neighbour outside them is the cleared 0 of dry glass.
uniform sampler2D u_heights;  // mm, 0: dry
uniform vec2 u_texel_mm;
layout(location = 0) out vec4 o_surface;  // normal u, v; height mm; water

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    // (i, j + 1), (i + 1, j + 1), (i + 1, j), (i, j).
    vec4 g = textureGather(u_heights, (vec2(p) + 1.0) / vec2(textureSize(u_heights, 0)));
    float h = g.w, hu = g.z, hv = g.x;
    if (h <= 0.0) {
        o_surface = vec4(0.0);
        return;
    }
    // Tangents (dx, 0, dh_u) and (0, dy, dh_v); their cross product is the normal.
    vec3 n = normalize(vec3(-(hu - h) * u_texel_mm.y, -(hv - h) * u_texel_mm.x, u_texel_mm.x * u_texel_mm.y));
    o_surface = vec4(n.xy, h, 1.0);
}
