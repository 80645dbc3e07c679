#version 450 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_color;

uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view_proj;

out vec3 v_world_pos;
out vec3 v_normal;
out vec4 v_color;
// The same position in every program made with it: the opaque pass lays the vehicles'
// depth with one (LitScene::depth) and shades them with others.
invariant gl_Position;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world_pos = world.xyz;
    v_normal = normalize(u_normal_matrix * a_normal);
    v_color = a_color;
    gl_Position = u_view_proj * world;
}
