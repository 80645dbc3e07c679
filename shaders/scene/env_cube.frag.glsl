#version 450 core
#include "common/sky.glsl"
// One face of the environment cube: the sky without the sun's disk (its highlight
// comes from the analytic sun term, so reflections don't show it twice).
in vec2 v_uv;
uniform vec3 u_face_forward, u_face_right, u_face_up;
layout(location = 0) out vec4 o_colour;
void main() {
    vec2 p = v_uv * 2.0 - 1.0;
    vec3 dir = u_face_forward + p.x * u_face_right + p.y * u_face_up;
    o_colour = vec4(sky_radiance(dir, false), 1.0);
}
