#version 450 core
#include "water/waves.glsl"
// A splash sheet's geometry step (WaterShading): a film of thrown-up water, so its
// normal faces the eye from either side; how thick it is (kind: 0.76 at 1/x of its rest
// thickness .. 1 at rest); how white; and how opaque, fading out only at its most
// tattered edges. A real crown or jet is clear water: thin, seen through, bright where
// it faces the sun or the sky at a grazing angle, white only at its rim, where the film
// has rolled up into a thick beaded edge that breaks into drops, and where it tears.
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
    float stretch = max(v_stretch, 1.0);
    // The rim: the film's free edge (cover: the share of a vertex's triangles drawn, under
    // 1 along the edge and round tears), beaded where the sheet gathers into drops.
    float rim = 1.0 - smoothstep(0.55, 0.92, v_cover);
    float beads = smoothstep(0.35, 0.7, foam_noise(v_cell * 0.9 + 11.3));
    // Torn: stretched nearly to tearing point, in streaks fixed in the film.
    float patches = foam_noise(v_cell * 0.3) * 0.65 + foam_noise(v_cell * 0.8) * 0.35;
    float torn = smoothstep(40.0, 130.0, stretch) * (0.3 + 0.5 * smoothstep(0.5, 0.85, patches));
    // Where the sheet or the jet meets the sea it churns the surface: a collar of foam.
    float collar = (1.0 - smoothstep(0.0, 0.06, v_world_pos.y - u_sea_level)) * (0.3 + 0.4 * beads);
    float whiteness = u_foam * (rim * (0.6 + 0.4 * beads) + torn + collar);
    o_normal = vec4(n, 1.0);
    float opacity = smoothstep(0.1, 0.35, v_cover);
    float thickness = clamp(1.0 / stretch + rim, 0.0, 1.0);  // the rim rolls up thick
    o_kind = vec4(0.76 + 0.24 * thickness, clamp(whiteness, 0.0, 0.95), opacity, 1.0);
}
