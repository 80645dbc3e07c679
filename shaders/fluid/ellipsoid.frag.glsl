#version 450 core
#include "fluid/common.glsl"
// Exact ray-ellipsoid hit: front (MIN blend) and back (MAX blend) view distances;
// hidden behind the opaque scene, nothing.
flat in vec3 v_centre;
flat in mat3 v_to_unit;
uniform sampler2D u_scene_depth;  // window depth of the scene
layout(location = 0) out float o_front;
layout(location = 1) out float o_back;

void main() {
    vec3 ray = view_ray(gl_FragCoord.xy);
    vec3 o = v_to_unit * (-v_centre);
    vec3 d = v_to_unit * ray;
    float a = dot(d, d), b = dot(o, d), c = dot(o, o) - 1.0;
    float disc = b * b - a * c;
    if (disc <= 0.0) discard;
    float s = sqrt(disc);
    float t0 = (-b - s) / a, t1 = (-b + s) / a;  // view distances (ray z is -1)
    float scene_ndc = texelFetch(u_scene_depth, ivec2(gl_FragCoord.xy), 0).r * 2.0 - 1.0;
    float scene_z = u_proj[3][2] / (scene_ndc + u_proj[2][2]);
    if (t0 <= 0.0 || t0 >= scene_z) discard;
    t1 = min(t1, scene_z);
    o_front = t0;
    o_back = t1;
}
