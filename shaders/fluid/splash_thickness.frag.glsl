#version 450 core
#include "fluid/common.glsl"
// A particle's gaussian thickness, added up (additive blend); none where the opaque
// scene or the liquid's body stands in front of the particle (both read at the
// full-resolution pixel under this target pixel's centre).
flat in float v_peak;
flat in float v_view_z;
flat in float v_sigma_px;
flat in float v_size_px;
uniform sampler2D u_scene_depth;  // window depth, full resolution
uniform sampler2D u_body_front;   // the body's front view distances, full resolution
uniform int u_scale;              // full-resolution pixels per target pixel (u_proj is the same)
layout(location = 0) out float o_thickness;

void main() {
    vec2 d = (gl_PointCoord - 0.5) * v_size_px;
    float q = dot(d, d) / (v_sigma_px * v_sigma_px);
    if (q > 9.0) discard;
    ivec2 full = ivec2(gl_FragCoord.xy) * u_scale + u_scale / 2;
    float scene_ndc = texelFetch(u_scene_depth, full, 0).r * 2.0 - 1.0;
    float scene_z = u_proj[3][2] / (scene_ndc + u_proj[2][2]);
    float body_z = texelFetch(u_body_front, full, 0).r;
    if (v_view_z >= min(scene_z, body_z)) discard;
    o_thickness = v_peak * exp(-0.5 * q);
}
