#version 450 core
#include "common/sky.glsl"
#include "common/lighting.glsl"
// One spray droplet per instance, a camera-facing quad from four strip vertices. Lit
// once per drop here rather than per pixel: the sky from above, the sun (shadowed),
// and a forward-scattering glow when looking towards the sun through the spray.
layout(location = 0) in vec4 a_drop;  // world position, radius in metres
uniform mat4 u_view_proj;
uniform vec3 u_eye;
uniform vec3 u_cam_right;
uniform vec3 u_cam_up;
uniform float u_pixel_m;     // world size of one pixel 1 m from the eye
uniform float u_min_pixels;  // smallest drawn diameter
uniform float u_opacity;
out vec2 v_corner;
out vec3 v_colour;
out float v_alpha;

void main() {
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0;
    vec3 p = a_drop.xyz;
    float r = max(a_drop.w, 0.0);
    float dist = max(length(p - u_eye), 1e-3);
    float drawn = max(r, 0.5 * u_min_pixels * u_pixel_m * dist);
    // Drops finer than the minimum spread their light over it (never below a faint haze)
    // and drops at the lens fade rather than filling the screen.
    float coverage = r * r / (drawn * drawn);
    v_alpha = u_opacity * max(coverage, 0.2) * smoothstep(0.3, 1.2, dist);

    vec3 to_sun = u_sun_dir;
    float forward = pow(max(dot(normalize(p - u_eye), to_sun), 0.0), 6.0);
    vec3 sky = textureLod(u_env, vec3(0, 1, 0), u_env_max_lod).rgb;
    vec3 sun = u_sun_radiance * sun_visibility(p, vec3(0)) * (0.2 + 1.2 * forward);
    v_colour = apply_fog(0.9 * (sky + sun), p, u_eye);

    v_corner = corner;
    gl_Position = u_view_proj * vec4(p + (u_cam_right * corner.x + u_cam_up * corner.y) * drawn, 1.0);
}
