#version 450 core
// Normals of the 3D reference's heights as the 2D path takes them (shape.frag.glsl):
// from the right and upper neighbours.
uniform sampler2D u_heights;  // mm, 0: dry
uniform vec2 u_texel_mm;
layout(location = 0) out vec4 o_surface;  // normal u, v; height mm; water

float height_mm(ivec2 p) { return texelFetch(u_heights, clamp(p, ivec2(0), textureSize(u_heights, 0) - 1), 0).r; }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float h = height_mm(p);
    if (h <= 0.0) {
        o_surface = vec4(0.0);
        return;
    }
    float hu = height_mm(p + ivec2(1, 0)), hv = height_mm(p + ivec2(0, 1));
    vec3 n = normalize(vec3(-(hu - h) * u_texel_mm.y, -(hv - h) * u_texel_mm.x, u_texel_mm.x * u_texel_mm.y));
    o_surface = vec4(n.xy, h, 1.0);
}
