#version 450 core
// A fin (Lengyel et al. 2001): a quad standing on a dusty edge, as tall as the shell
// stack there, textured with a vertical slice of the fibre volume. It shows only
// where the surface is seen edge-on, where the shells would show as lines.

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_amount;
layout(location = 3) in vec2 a_fin;  // along the edge (m), height 0..1
layout(location = 4) in uint a_vertex;  // the dusty vertex it stands on

layout(std430, binding = 1) readonly buffer VertexLight { vec4 vertex_light[]; };  // light, fog

uniform mat4 u_view_proj;
uniform vec3 u_eye;
uniform float u_height_m;
uniform float u_tile_m;

out vec3 v_base_pos;
out vec3 v_normal;
out float v_amount;
out float v_height;
out vec2 v_fin_uv;
out float v_fin_fade;
out vec3 v_light;
out vec4 v_fog;

void main() {
    vec3 n = normalize(a_normal);
    vec3 p = a_position + n * (a_fin.y * u_height_m * a_amount);
    float facing = abs(dot(n, normalize(u_eye - a_position)));
    v_base_pos = a_position;
    v_normal = n;
    v_amount = a_amount;
    v_height = a_fin.y;
    v_fin_uv = vec2(a_fin.x / u_tile_m, dot(a_position.xz, vec2(0.71, 0.29)) / u_tile_m);
    v_fin_fade = 1.0 - smoothstep(0.15, 0.4, facing);
    v_light = vertex_light[2 * a_vertex].rgb;
    v_fog = vertex_light[2 * a_vertex + 1];
    // Fins facing the eye are folded away (zero area) rather than drawn transparent.
    gl_Position = v_fin_fade > 0.0 ? u_view_proj * vec4(p, 1.0) : vec4(0.0, 0.0, 2.0, 1.0);
}
