#version 450 core
// Temporal upsampling's resolve (TemporalPass), at the scene's size: this frame's
// tone-mapped pixel (drawn with a sub-pixel jitter) blended into the last resolved frame,
// read where this pixel's point was in it (the nearest point around it: see below) and
// clamped to the range of its 3x3 neighbourhood less a corner, so that what moved or came
// into view leaves no ghost. Most of the neighbourhood comes from the fine derivatives,
// not from fetches: a fragment shader runs a quad at a time, and on llvmpipe a fetch
// costs as much as the rest of the pixel's arithmetic.
// Blended in the display's encoding: what it smooths is edges, where that is what the eye
// compares.
// FROM_HDR: u_current is the HDR scene colour and the tone map is done here; it rises
// channel by channel, so the neighbourhood's range is taken in HDR and its two ends tone
// mapped (three tone maps a pixel, not five).
// VEHICLE: a second candidate for where the point was, through the last pose of the
// vehicle nearest the eye; TemporalPass draws it only over that vehicle's pixels.
#ifdef FROM_HDR
#include "common/tonemap.glsl"
uniform float u_exposure;
#endif
uniform sampler2D u_current;  // this frame (texels): tone-mapped, or HDR with FROM_HDR
uniform sampler2D u_history;  // the last resolved frame, bilinear
uniform sampler2D u_depth;    // this frame's window depth
uniform mat4 u_reproject;     // this frame's unjittered NDC -> the last frame's clip space, the world still
uniform mat4 u_reproject_vehicle;  // the same for a point on the vehicle nearest the eye
uniform float u_current_weight;  // 1: no history (the first frame, a resize)
layout(location = 0) out vec4 o_colour;

// A value at the pixel beside this one in its quad, in x (beside_x) or in y (beside_y),
// from the fine derivatives; `s` is the side it is on (+1 or -1).
vec3 beside_x(vec3 v, ivec2 s) { return v + float(s.x) * dFdxFine(v); }
vec3 beside_y(vec3 v, ivec2 s) { return v + float(s.y) * dFdyFine(v); }
float beside_x(float v, ivec2 s) { return v + float(s.x) * dFdxFine(v); }
float beside_y(float v, ivec2 s) { return v + float(s.y) * dFdyFine(v); }

void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
    const ivec2 size = textureSize(u_current, 0);
    vec3 c = texelFetch(u_current, p, 0).rgb;
    // Its 3x3 neighbourhood but for the corner away from its quad: the quad's three
    // others from the fine derivatives, the two outside it beside it fetched, and the
    // two outside corners the quad's others fetched, again from the derivatives. The
    // range covers both sides of an edge in x, in y and along the diagonals, which the
    // jittered frames' blend needs to keep.
    const ivec2 s = ivec2((p.x & 1) == 0 ? 1 : -1, (p.y & 1) == 0 ? 1 : -1);
    const ivec2 p_out_x = clamp(p - ivec2(s.x, 0), ivec2(0), size - 1);
    const ivec2 p_out_y = clamp(p - ivec2(0, s.y), ivec2(0), size - 1);
    const vec3 across = beside_x(c, s);
    const vec3 out_x = texelFetch(u_current, p_out_x, 0).rgb;
    const vec3 out_y = texelFetch(u_current, p_out_y, 0).rgb;
    const vec3 n[7] = {across, beside_y(c, s), beside_y(across, s), out_x, out_y, beside_x(out_y, s), beside_y(out_x, s)};
    vec3 lo = c, hi = c;
    for (int i = 0; i < 7; ++i) {
        lo = min(lo, n[i]);
        hi = max(hi, n[i]);
    }
#ifdef FROM_HDR
    c = tonemap(c * u_exposure);
    lo = tonemap(lo * u_exposure);
    hi = tonemap(hi * u_exposure);
#endif

    // The point reprojected is the nearest in the same neighbourhood: at a near
    // object's silhouette the pixels around it, whichever side their sample fell on
    // this frame, take the near object's motion (its edge's history moves with it),
    // not a mix of its and the background's, which this frame's stairs would pick
    // between (a moving edge drawn as this frame's stairs, one scene pixel each).
    const float d = texelFetch(u_depth, p, 0).r;
    const float d_across = beside_x(d, s);
    const float d_out_x = texelFetch(u_depth, p_out_x, 0).r;
    const float d_out_y = texelFetch(u_depth, p_out_y, 0).r;
    const float depth = min(min(min(d, d_across), min(beside_y(d, s), beside_y(d_across, s))),
                            min(min(d_out_x, d_out_y), min(beside_x(d_out_y, s), beside_y(d_out_x, s))));
    const vec2 ndc = (gl_FragCoord.xy / vec2(size)) * 2.0 - 1.0;
    const vec4 point = vec4(ndc, depth * 2.0 - 1.0, 1.0);
    vec4 before = u_reproject * point;
    vec2 uv = (before.xy / before.w) * 0.5 + 0.5;
    vec3 h = texture(u_history, uv).rgb;
#ifdef VEHICLE
    // Two candidates for where the point was (the world's, the vehicle's): the one whose
    // history is nearer this frame's colour.
    const vec4 before_vehicle = u_reproject_vehicle * point;
    const vec2 uv_vehicle = (before_vehicle.xy / before_vehicle.w) * 0.5 + 0.5;
    const vec3 h_vehicle = texture(u_history, uv_vehicle).rgb;
    if (dot(h_vehicle - c, h_vehicle - c) < dot(h - c, h - c)) {
        before = before_vehicle;
        uv = uv_vehicle;
        h = h_vehicle;
    }
#endif
    h = clamp(h, lo, hi);
    // Off the last frame's edge there is nothing to blend with.
    const bool inside = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0))) && before.w > 0.0;
    o_colour = vec4(mix(h, c, inside ? u_current_weight : 1.0), 1.0);
}
