#version 450 core
// One metaball of the rain height map: a quad reaching kMetaballReach radii around the
// drop, in the glass's coordinates (metres) mapped onto the whole texture.
layout(location = 0) in vec4 a_drop;  // centre u, v (m), radius (m), unused
uniform vec2 u_glass_size_m;
uniform float u_radius_scale;
uniform float u_reach;
out vec2 v_offset;  // in radii from the centre
flat out float v_radius_mm;
void main() {
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0;
    float r = a_drop.z * u_radius_scale;
    vec2 p = a_drop.xy + corner * (u_reach * r);
    v_offset = corner * u_reach;
    v_radius_mm = r * 1000.0;
    gl_Position = vec4(p / u_glass_size_m * 2.0 - 1.0, 0.0, 1.0);
}
