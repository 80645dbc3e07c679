#version 450 core
// A fin (Lengyel et al. 2001): a quad standing on a dusty edge, as tall as the shell
// stack there, textured with a vertical slice of the fibre volume. It shows only
// where the surface is seen edge-on, where the shells would show as lines.
#include "dust/dust_vertex.glsl"

layout(location = 3) in vec2 a_fin;  // along the edge (m), height 0..1
layout(location = 4) in uint a_vertex;  // the dusty vertex it stands on

uniform vec3 u_eye;
uniform float u_tile_m;

void main() {
    float facing = abs(dot(normalize(a_normal), normalize(u_eye - a_position)));
    float fade = 1.0 - smoothstep(0.15, 0.4, facing);
    vec2 uv = vec2(a_fin.x / u_tile_m, dot(a_position.xz, vec2(0.71, 0.29)) / u_tile_m);
    vec3 p = dust_point(a_fin.y, a_vertex, uv, fade);
    // Fins facing the eye are folded away (zero area) rather than drawn transparent.
    gl_Position = fade > 0.0 ? u_view_proj * vec4(p, 1.0) : vec4(0.0, 0.0, 2.0, 1.0);
}
