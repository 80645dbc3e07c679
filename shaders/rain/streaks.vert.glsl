#version 450 core
// One rain streak per two vertices (GL_LINES, no vertex buffer; RainStreakPass). A drop
// has a fixed place in the world that falls with time and wraps into a box about the
// eye; its streak runs from where it is to where it was one exposure ago.
uniform mat4 u_view_proj;
uniform vec3 u_eye;
uniform float u_time_s;
uniform vec3 u_box_m;
uniform vec3 u_fall_mps;
uniform float u_exposure_s;
uniform float u_near_m;
uniform float u_opacity;
uniform vec3 u_colour;  // lit by the grey sky they fall from
out float v_alpha;
out vec3 v_colour;

// Three numbers in [0,1) from a drop's index (an integer hash: the same on every GPU).
vec3 drop_seed(uint i) {
    uvec3 v = uvec3(i, i ^ 0x9e3779b9u, i + 0x7f4a7c15u) * uvec3(1597334673u, 3812015801u, 2798796415u);
    v = (v.yzx ^ (v >> 16u)) * uvec3(2246822519u, 3266489917u, 668265263u);
    v ^= v >> 15u;
    return vec3(v >> 8u) * (1.0 / 16777216.0);
}

void main() {
    uint drop = uint(gl_VertexID) >> 1u;
    vec3 seed = drop_seed(drop);
    float speed = 0.8 + 0.4 * fract(seed.x * 7.0);  // bigger drops fall faster
    vec3 fall = u_fall_mps * speed;
    vec3 head = u_eye + mod(seed * u_box_m + fall * u_time_s - u_eye, u_box_m) - 0.5 * u_box_m;
    vec3 p = (gl_VertexID & 1) == 0 ? head : head - fall * u_exposure_s;
    float dist = length(head - u_eye);
    // Faded in past the near limit and out before the box's sides, where drops wrap.
    float reach = 0.5 * min(u_box_m.x, u_box_m.z);
    v_alpha = u_opacity * smoothstep(u_near_m, u_near_m + 1.5, dist) * (1.0 - smoothstep(0.55 * reach, 0.95 * reach, dist));
    v_colour = u_colour;
    gl_Position = dist < u_near_m ? vec4(2.0, 2.0, 2.0, 1.0) : u_view_proj * vec4(p, 1.0);
}
