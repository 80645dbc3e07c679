#version 450 core
#include "fluid/common.glsl"
// Normals of a front and a back depth map (seed eqs. 3.2-3.4): the cross product of
// the view-space position's screen derivatives, each the one-sided difference with
// the smaller depth change. Front normals face the viewer, back normals face away.
uniform sampler2D u_front;
uniform sampler2D u_back;
layout(location = 0) out vec4 o_front_normal;
layout(location = 1) out vec4 o_back_normal;

vec3 position_at(sampler2D map, ivec2 p) {
    float z = texelFetch(map, clamp_to_rect(p), 0).r;
    return has_depth(z) ? view_ray(vec2(p) + 0.5) * z : vec3(0.0);
}

vec3 normal_of(sampler2D map, ivec2 p, float facing) {
    vec3 c = position_at(map, p);
    if (c == vec3(0.0)) return vec3(0.0);
    vec3 xp = position_at(map, p + ivec2(1, 0)), xm = position_at(map, p - ivec2(1, 0));
    vec3 yp = position_at(map, p + ivec2(0, 1)), ym = position_at(map, p - ivec2(0, 1));
    vec3 dx1 = xp - c, dx0 = c - xm, dy1 = yp - c, dy0 = c - ym;
    bool hx1 = xp != vec3(0.0), hx0 = xm != vec3(0.0), hy1 = yp != vec3(0.0), hy0 = ym != vec3(0.0);
    vec3 dx = !hx0 ? dx1 : !hx1 ? dx0 : (abs(dx1.z) < abs(dx0.z) ? dx1 : dx0);
    vec3 dy = !hy0 ? dy1 : !hy1 ? dy0 : (abs(dy1.z) < abs(dy0.z) ? dy1 : dy0);
    if (!(hx0 || hx1) || !(hy0 || hy1)) return vec3(0.0, 0.0, facing);  // a lone pixel
    vec3 n = normalize(cross(dx, dy));
    return n * facing;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    o_front_normal = vec4(normal_of(u_front, p, 1.0), 0.0);
    o_back_normal = vec4(normal_of(u_back, p, -1.0), 0.0);
}
