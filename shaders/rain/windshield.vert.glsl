#version 450 core
#include "common/sky.glsl"
// The windshield in car model space, placed at the car's pose; carries the glass's
// own coordinates and tangents for the drops' height map, and the sky overhead (the
// same for every pixel: computed per vertex, not per pixel).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_uv_m;
layout(location = 2) in vec3 a_tangent_u;
layout(location = 3) in vec3 a_tangent_v;
uniform mat4 u_model;
uniform mat4 u_view_proj;
out vec3 v_world;
out vec2 v_uv_m;
out vec3 v_tangent_u, v_tangent_v;
flat out vec3 v_sky_overhead;
void main() {
    vec4 w = u_model * vec4(a_position, 1.0);
    v_world = w.xyz;
    v_uv_m = a_uv_m;
    v_tangent_u = mat3(u_model) * a_tangent_u;
    v_tangent_v = mat3(u_model) * a_tangent_v;
    v_sky_overhead = sky_radiance(vec3(0.0, 1.0, 0.0), false);
    gl_Position = u_view_proj * w;
}
