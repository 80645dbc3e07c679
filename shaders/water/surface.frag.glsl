#version 450 core
#include "water/waves.glsl"
// The sea surface's geometry step (WaterShading): its normal, from the wave grid's
// slopes plus wind ripples, and how much of a breaking crest each pixel is. The
// full shading follows in water/shade.frag.glsl.
in vec3 v_world_pos;
uniform vec3 u_eye;
uniform float u_time_s;
uniform int u_has_grid;
uniform sampler2D u_slopes;  // dh/dx, dh/dz, Laplacian per grid cell
uniform vec2 u_grid_origin;
uniform float u_grid_spacing;
uniform int u_grid_size;
uniform float u_ripples;
layout(location = 0) out vec4 o_normal;
layout(location = 1) out vec4 o_kind;  // 0.5 = sea, crest weight, how stirred it is

// Slope (dh/dx, dh/dz) of the wave grid at xz, how much of a breaking crest it is
// (steep, and peaked: negative Laplacian) and how stirred (a wake: slopes and
// curvature far below a crest's, which the mirror alone barely shows from a low
// camera; sharply curved, where a hull is pushing it, churned white). Fades to flat
// over the last cell, where the mesh is held at rest.
vec2 grid_slope(vec2 xz, out float crest, out float stirred) {
    crest = 0.0;
    stirred = 0.0;
    if (u_has_grid == 0) return vec2(0.0);
    float n = float(u_grid_size);
    vec2 cell = (xz - u_grid_origin) / u_grid_spacing;
    float inside = min(min(cell.x, cell.y), min(n - 1.0 - cell.x, n - 1.0 - cell.y));
    if (inside <= 0.0) return vec2(0.0);
    vec3 s = texture(u_slopes, (cell + 0.5) / n).xyz;
    vec2 slope = s.xy * min(inside, 1.0);
    float steep = length(slope);
    float curved = abs(s.z) * min(inside, 1.0);
    crest = smoothstep(0.25, 0.6, steep) * smoothstep(-0.2, -1.0, s.z) + 0.5 * smoothstep(0.5, 1.0, steep) +
            0.8 * smoothstep(0.09, 0.4, curved);
    stirred = smoothstep(0.006, 0.05, steep + 0.1 * curved);
    return slope;
}

void main() {
    float dist = length(u_eye - v_world_pos);
    float crest, stirred;
    vec2 slope = grid_slope(v_world_pos.xz, crest, stirred) + ripple_slope(v_world_pos.xz, u_time_s, dist) * u_ripples;
    o_normal = vec4(normalize(vec3(-slope.x, 1.0, -slope.y)), 1.0);
    o_kind = vec4(0.5, clamp(crest, 0.0, 1.0), stirred, 1.0);
}
