#version 450 core
#include "fluid/common.glsl"
// One point sprite per particle, sized to the screen bounds of its ellipsoid's
// bounding sphere; the fragment stage ray-casts the ellipsoid itself (Sigg et al. 2006).
struct Ellipsoid { vec4 centre; vec4 axis[3]; };
layout(std430, binding = 0) readonly buffer Particles { Ellipsoid particles[]; };
uniform mat4 u_view;
flat out vec3 v_centre;    // view space
flat out mat3 v_to_unit;   // view space -> the unit sphere's space

void main() {
    Ellipsoid e = particles[gl_VertexID];
    mat3 view3 = mat3(u_view);
    mat3 axes = mat3(view3 * e.axis[0].xyz, view3 * e.axis[1].xyz, view3 * e.axis[2].xyz);
    v_centre = (u_view * vec4(e.centre.xyz, 1.0)).xyz;
    v_to_unit = inverse(axes);
    float radius = max(length(axes[0]), max(length(axes[1]), length(axes[2])));
    gl_Position = u_proj * vec4(v_centre, 1.0);
    float z = max(-v_centre.z - radius, 0.05);  // the nearest point of the bounding sphere
    gl_PointSize = clamp(2.0 * radius * u_proj[1][1] * 0.5 * u_viewport.y / z + 2.0, 1.0, 255.0);
    if (-v_centre.z < -radius) gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // behind the eye
}
