#version 450 core
#include "common/sky.glsl"
#include "common/lighting.glsl"
// One spray droplet per instance, a camera-facing quad from four strip vertices. Lit
// once per drop here rather than per pixel. A drop is a small clear lens: it shows the
// sky it refracts (a little darker and greener than the sky around it), a forward-
// scattering glow looking towards the sun, and a small highlight: the sun mirrored in
// its surface, where the drop's normal is halfway between the eye and the sun, brighter
// at grazing angles (Fresnel) and for drops large enough to resolve (a drop spread over
// its blur circle spreads its highlight too, so fine spray never reads as white points).
layout(location = 0) in vec4 a_drop;  // world position, radius in metres
uniform mat4 u_view_proj;
uniform vec3 u_eye;
uniform vec3 u_cam_right;
uniform vec3 u_cam_up;
uniform float u_pixel_m;     // world size of one pixel 1 m from the eye
uniform float u_min_pixels;  // smallest drawn diameter
uniform float u_blur_m;      // the eye's blur circle: a drop near it is a soft disc this wide
uniform float u_opacity;
out vec2 v_corner;
out vec3 v_colour;
out float v_alpha;
out vec2 v_glint_at;  // where on the disc the sun is mirrored
out vec3 v_glint;     // the highlight's peak
out float v_sharp;    // 1: the drop is drawn at its own size (in focus, resolved)

void main() {
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0;
    vec3 p = a_drop.xyz;
    float r = max(a_drop.w, 0.0);
    float dist = max(length(p - u_eye), 1e-3);
    // Out of focus near the eye (the blur circle has the same world size at any
    // distance), and at least min_pixels wide far off; either way the drop's light is
    // spread over what is drawn, so it fades instead of staying a crisp dot.
    float drawn = max(max(r, 0.5 * u_blur_m), 0.5 * u_min_pixels * u_pixel_m * dist);
    float coverage = r * r / (drawn * drawn);
    // Drops within a metre of the eye fade out rather than fill the screen.
    v_sharp = smoothstep(0.5, 0.9, coverage);
    v_alpha = u_opacity * max(coverage, 0.1) * smoothstep(0.6, 1.6, dist);

    vec3 d = normalize(p - u_eye);
    float toward = max(dot(d, u_sun_dir), 0.0);
    float forward = toward * toward;
    forward *= forward;
    forward *= forward;  // toward^8
    vec3 sky = textureLod(u_env, vec3(0, 1, 0), u_env_max_lod).rgb;
    float sunlit = sun_visibility(p, vec3(0));  // once: the glow and the highlight share it
    vec3 sun = u_sun_radiance * sunlit * (0.03 + 0.5 * forward);
    v_colour = apply_fog(0.85 * sky * vec3(0.88, 0.95, 0.97) + sun, p, u_eye);
    vec3 h = normalize(u_sun_dir - d);
    v_glint_at = vec2(dot(h, u_cam_right), dot(h, u_cam_up));
    float fresnel = 0.02 + 0.98 * pow(1.0 - clamp(dot(h, -d), 0.0, 1.0), 5.0);
    v_glint = u_sun_radiance * sunlit * (0.6 + 3.0 * fresnel) * min(coverage, 1.0) *
              exp(-dist * 0.0012) * smoothstep(0.6, 1.6, dist);  // through the fog (apply_fog)

    v_corner = corner;
    // Drawn at the drop's front, so a bead resting on a sheet's rim is not hidden in it.
    gl_Position = u_view_proj * vec4(p - d * r + (u_cam_right * corner.x + u_cam_up * corner.y) * drawn, 1.0);
}
