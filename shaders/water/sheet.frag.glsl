#version 450 core
#include "water/waves.glsl"
// A splash sheet's geometry step (WaterShading): a film of thrown-up water, so its
// normal faces the eye from either side; how thin it has stretched (kind: 0.76 at 1/x
// of its rest thickness .. 1 at rest); and how white it is: torn patches fixed in the
// film (they stretch with it), more of them high up and where it has stretched thin;
// and how opaque it is, fading out towards its torn edges.
in vec3 v_world_pos;
in vec3 v_normal;
in vec2 v_cell;
in float v_stretch;
in float v_cover;
uniform vec3 u_eye;
uniform float u_sea_level;
uniform float u_foam;
layout(location = 0) out vec4 o_normal;
layout(location = 1) out vec4 o_kind;  // sheet kind with its thickness, whiteness, opacity

void main() {
    vec3 n = normalize(v_normal);
    if (dot(n, u_eye - v_world_pos) < 0.0) n = -n;
    // Thrown water is never a flat pane: ripple the film's normal (fixed in the film), in
    // swells several vertices wide; a ripple per vertex made the film read as facets.
    vec2 wobble = vec2(foam_noise(v_cell * 0.18 + 3.1), foam_noise(v_cell * 0.18 + 7.7)) - 0.5;
    n = normalize(n + 0.35 * vec3(wobble.x, 0.0, wobble.y));
    float height = v_world_pos.y - u_sea_level;
    float stretch = max(v_stretch, 1.0);
    // Clear where the film is thick, white where it has stretched thin towards the rim
    // and where it has begun to tear (its cover), in streaks fixed in the film.
    float patches = foam_noise(v_cell * 0.3) * 0.65 + foam_noise(v_cell * 0.8) * 0.35;
    float whiteness = u_foam * (0.1 + 0.15 * smoothstep(0.2, 1.5, height) + 0.3 * smoothstep(0.5, 0.85, patches) +
                                0.45 * smoothstep(2.0, 8.0, stretch) + 0.3 * (1.0 - smoothstep(0.5, 1.0, v_cover)));
    o_normal = vec4(n, 1.0);
    // The film thins out to nothing towards a torn or ragged edge rather than ending in
    // a hard polygon outline.
    float opacity = smoothstep(0.15, 1.0, v_cover);
    o_kind = vec4(0.76 + 0.24 / stretch, clamp(whiteness, 0.0, 0.9), opacity, 1.0);
}
