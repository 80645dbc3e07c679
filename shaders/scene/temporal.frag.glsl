#version 450 core
// Temporal upsampling's resolve (TemporalPass), at the scene's size: this frame's
// tone-mapped pixel (drawn with a sub-pixel jitter) blended into the last resolved frame,
// read where this pixel's point was in it and clamped to the range of this pixel, the four
// beside it and its quad's diagonal, so that what moved or came into view leaves no
// ghost. The quad's pixels come from the fine derivatives, not from fetches: a fragment
// shader runs a quad at a time, and on llvmpipe a fetch costs as much as the rest of the
// pixel's arithmetic.
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
uniform mat4 u_reproject;     // this frame's NDC -> the last frame's clip space, the world still
uniform mat4 u_reproject_vehicle;  // the same for a point on the vehicle nearest the eye
uniform float u_current_weight;  // 1: no history (the first frame, a resize)
layout(location = 0) out vec4 o_colour;

// The history at uv through a Catmull-Rom spline (sharp, unlike bilinear) in five
// bilinear fetches: the middle 2x2 texels' weights in one, one each side, the corners
// (the smallest weights) left out and the sum normalised.
vec3 history_at(vec2 uv) {
    const vec2 size = vec2(textureSize(u_history, 0));
    const vec2 pos = uv * size;
    const vec2 t1 = floor(pos - 0.5) + 0.5;
    const vec2 f = pos - t1;
    const vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
    const vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
    const vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
    const vec2 w3 = f * f * (-0.5 + 0.5 * f);
    const vec2 w12 = w1 + w2;
    const vec2 t12 = (t1 + w2 / w12) / size, t0 = (t1 - 1.0) / size, t3 = (t1 + 2.0) / size;
    const float wc = w12.x * w12.y, wl = w0.x * w12.y, wr = w3.x * w12.y, wb = w12.x * w0.y, wt = w12.x * w3.y;
    const vec3 sum = texture(u_history, t12).rgb * wc + texture(u_history, vec2(t0.x, t12.y)).rgb * wl +
                     texture(u_history, vec2(t3.x, t12.y)).rgb * wr + texture(u_history, vec2(t12.x, t0.y)).rgb * wb +
                     texture(u_history, vec2(t12.x, t3.y)).rgb * wt;
    return sum / (wc + wl + wr + wb + wt);
}

void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
    const ivec2 size = textureSize(u_current, 0);
    vec3 c = texelFetch(u_current, p, 0).rgb;
    // The four beside it: the two within its quad from the fine derivatives, the two
    // outside it fetched. With the quad's diagonal, the range covers both sides of an
    // edge in x and in y, which the jittered frames' blend needs to keep.
    const ivec2 s = ivec2((p.x & 1) == 0 ? 1 : -1, (p.y & 1) == 0 ? 1 : -1);
    const vec3 across = c + float(s.x) * dFdxFine(c);
    const vec3 beside = c + float(s.y) * dFdyFine(c);
    const vec3 diagonal = across + float(s.y) * dFdyFine(across);
    const vec3 out_x = texelFetch(u_current, clamp(p - ivec2(s.x, 0), ivec2(0), size - 1), 0).rgb;
    const vec3 out_y = texelFetch(u_current, clamp(p - ivec2(0, s.y), ivec2(0), size - 1), 0).rgb;
    const vec3 corner_x = out_y + float(s.x) * dFdxFine(out_y);
    const vec3 corner_y = out_x + float(s.y) * dFdyFine(out_x);
    vec3 lo = min(min(min(c, across), min(beside, diagonal)), min(min(out_x, out_y), min(corner_x, corner_y)));
    vec3 hi = max(max(max(c, across), max(beside, diagonal)), max(max(out_x, out_y), max(corner_x, corner_y)));
#ifdef FROM_HDR
    c = tonemap(c * u_exposure);
    lo = tonemap(lo * u_exposure);
    hi = tonemap(hi * u_exposure);
#endif

    const float d = texelFetch(u_depth, p, 0).r;
    const float d_across = d + float(s.x) * dFdxFine(d);
    const float d_out_x = texelFetch(u_depth, clamp(p - ivec2(s.x, 0), ivec2(0), size - 1), 0).r;
    const float d_out_y = texelFetch(u_depth, clamp(p - ivec2(0, s.y), ivec2(0), size - 1), 0).r;
    const float depth = min(min(min(d, d_across), min(d + float(s.y) * dFdyFine(d), d_across + float(s.y) * dFdyFine(d_across))),
                            min(min(d_out_x, d_out_y), min(d_out_y + float(s.x) * dFdxFine(d_out_y), d_out_x + float(s.y) * dFdyFine(d_out_x))));
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
