#version 450 core
// Splash sheet vertices, already in world space.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_cell;
layout(location = 3) in float a_stretch;
layout(location = 4) in float a_cover;
uniform mat4 u_view_proj;
out vec3 v_world_pos;
out vec3 v_normal;
out vec2 v_cell;
out float v_stretch;
out float v_cover;
void main() {
    v_world_pos = a_position;
    v_normal = a_normal;
    v_cell = a_cell;
    v_stretch = a_stretch;
    v_cover = a_cover;
    gl_Position = u_view_proj * vec4(a_position, 1.0);
}
