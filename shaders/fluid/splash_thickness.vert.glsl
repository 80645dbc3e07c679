#version 450 core
#include "fluid/common.glsl"
// One soft point sprite per splash particle into the low-resolution thickness target
// (u_viewport and u_proj are that target's): a gaussian at least a few target pixels
// wide, holding the particle's volume, so a lone drop is a faint smudge and a dense
// cloud adds up to a thick layer.
struct Ellipsoid { vec4 centre; vec4 axis[3]; };
layout(std430, binding = 0) readonly buffer Particles { Ellipsoid particles[]; };
uniform mat4 u_view;
uniform float u_soft_pixels;  // the least gaussian sigma, in target pixels
flat out float v_peak;        // thickness at the centre, metres
flat out float v_view_z;      // the particle's view distance
flat out float v_sigma_px;
flat out float v_size_px;     // the sprite's width in target pixels

void main() {
    Ellipsoid e = particles[gl_VertexID];
    vec3 c = (u_view * vec4(e.centre.xyz, 1.0)).xyz;
    float r = max(length(e.axis[0].xyz), max(length(e.axis[1].xyz), length(e.axis[2].xyz)));
    float z = max(-c.z, 0.05);
    float px_per_m = u_proj[1][1] * 0.5 * u_viewport.y / z;
    // A sphere's thickness integrates to its volume 4/3 pi r^3; a gaussian of peak A and
    // width sigma to 2 pi A sigma^2: the same volume at any softness.
    float sigma_m = max(0.6 * r, u_soft_pixels / px_per_m);
    v_peak = (2.0 / 3.0) * r * r * r / (sigma_m * sigma_m);
    v_sigma_px = sigma_m * px_per_m;
    v_view_z = -c.z;
    gl_Position = u_proj * vec4(c, 1.0);
    v_size_px = clamp(6.0 * v_sigma_px + 1.0, 1.0, 63.0);
    gl_PointSize = v_size_px;
    if (-c.z < 0.05) gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // at or behind the eye
}
