#version 450 core
// Fast approximate anti-aliasing on the tone-mapped frame, after the algorithm Lottes
// describes for FXAA 3.11 ("FXAA", NVIDIA whitepaper, 2009; "FXAA 3.11" notes, 2011):
// find where the luma of the 3x3 neighbourhood jumps, decide whether that edge runs
// along x or y, walk along it both ways until the jump ends, and resample the pixel
// with a bilinear tap moved across the edge by how far it sits from the nearer end
// (long shallow stairs become ramps); single-pixel specks get a share of their
// neighbourhood's average instead (the subpixel term). Drawn at the scene's own size.
uniform sampler2D u_display;  // sRGB-encoded, bilinear
uniform float u_subpixel;     // 0: edges only .. 1: specks fully softened
uniform float u_threshold;    // the least contrast, relative to the brightest luma, that counts as an edge
uniform float u_threshold_min;  // and in absolute terms: dark noise is left alone
layout(location = 0) out vec4 o_colour;

// The gamma-encoded green stands in for luma (Lottes' cheaper option): one channel, so a
// gather reads four neighbours at once. Edges between colours of equal green are missed.
float luma_uv(vec2 uv) { return textureLod(u_display, uv, 0.0).g; }

void main() {
    const ivec2 size = textureSize(u_display, 0);
    const vec2 texel = 1.0 / vec2(size);
    const ivec2 p = ivec2(gl_FragCoord.xy);
    const ivec2 last = size - 1;
    const vec3 centre = texelFetch(u_display, p, 0).rgb;
    // The 3x3 neighbourhood in two gathers and two fetches: each gather reads the 2x2
    // texels around a point a quarter texel off the centre (no rounding can pick
    // another 2x2), the one up and right of it and, offset, the one down and left.
    const vec2 gather_at = (vec2(p) + 0.75) * texel;
    const vec4 up_right = textureGather(u_display, gather_at, 1);  // N, NE, E, M
    const vec4 down_left = textureGatherOffset(u_display, gather_at, ivec2(-1, -1), 1);  // W, M, S, SW
    float m = centre.g, n = up_right.x, ne = up_right.y, e = up_right.z;
    float w = down_left.x, s = down_left.z, sw = down_left.w;
    float nw = texelFetch(u_display, clamp(p + ivec2(-1, 1), ivec2(0), last), 0).g;
    float se = texelFetch(u_display, clamp(p + ivec2(1, -1), ivec2(0), last), 0).g;

    float hi = max(max(max(n, s), max(e, w)), m), lo = min(min(min(n, s), min(e, w)), m);
    float range = hi - lo;
    // No branch out for flat pixels (a CPU rasteriser runs both sides): they end with a
    // zero offset, which resamples the centre itself.
    bool is_edge = range >= max(u_threshold_min, hi * u_threshold);

    // Which way the edge runs: the second differences across rows (horizontal edge) and
    // across columns (vertical edge), the centre line weighted twice.
    float across_rows = abs(n + s - 2.0 * m) * 2.0 + abs(ne + se - 2.0 * e) + abs(nw + sw - 2.0 * w);
    float across_cols = abs(e + w - 2.0 * m) * 2.0 + abs(ne + nw - 2.0 * n) + abs(se + sw - 2.0 * s);
    bool horizontal = across_rows >= across_cols;

    // The neighbour on the far side of the edge: the one with the larger luma step.
    float before = horizontal ? s : w, after = horizontal ? n : e;
    float step_before = before - m, step_after = after - m;
    bool towards_after = abs(step_after) >= abs(step_before);
    float gradient = max(abs(step_before), abs(step_after));
    float across = (horizontal ? texel.y : texel.x) * (towards_after ? 1.0 : -1.0);
    // The luma halfway between this pixel and that neighbour: the edge's own level.
    float edge_luma = 0.5 * (m + (towards_after ? after : before));

    // Walk along the edge on the seam between the two lines (one bilinear tap reads the
    // average of both), in growing steps, until the average leaves the edge's level.
    vec2 seam = (vec2(p) + 0.5) * texel;
    if (horizontal) seam.y += 0.5 * across; else seam.x += 0.5 * across;
    const vec2 along = horizontal ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
    const float kSteps[4] = float[4](1.0, 1.5, 2.0, 4.0);
    float threshold = gradient * 0.25;
    vec2 neg = seam, pos = seam;
    float end_neg = 0.0, end_pos = 0.0;
    bool done_neg = false, done_pos = false;
    for (int i = 0; i < 4; ++i) {
        if (!done_neg) neg -= along * kSteps[i];
        if (!done_pos) pos += along * kSteps[i];
        if (!done_neg) end_neg = luma_uv(neg) - edge_luma;
        if (!done_pos) end_pos = luma_uv(pos) - edge_luma;
        done_neg = done_neg || abs(end_neg) >= threshold;
        done_pos = done_pos || abs(end_pos) >= threshold;
    }
    float dist_neg = horizontal ? seam.x - neg.x : seam.y - neg.y;
    float dist_pos = horizontal ? pos.x - seam.x : pos.y - seam.y;
    // Only the nearer end matters, and only if the edge's luma there moves the other way
    // from this pixel's (the stair really ends there rather than the edge fading out).
    bool nearer_neg = dist_neg < dist_pos;
    float nearer = min(dist_neg, dist_pos);
    bool centre_below = m - edge_luma < 0.0;
    bool good_end = ((nearer_neg ? end_neg : end_pos) < 0.0) != centre_below;
    float edge_offset = good_end ? 0.5 - nearer / (dist_neg + dist_pos) : 0.0;

    // Subpixel: how far the centre stands out from the 3x3 average, as a share of the range.
    float average = (2.0 * (n + s + e + w) + (ne + nw + se + sw)) / 12.0;
    float speck = clamp(abs(average - m) / max(range, 1e-4), 0.0, 1.0);
    float smooth_speck = (3.0 - 2.0 * speck) * speck * speck;
    float subpixel_offset = smooth_speck * smooth_speck * u_subpixel;

    float offset = is_edge ? max(edge_offset, subpixel_offset) : 0.0;
    vec2 uv = (vec2(p) + 0.5) * texel;
    if (horizontal) uv.y += offset * across; else uv.x += offset * across;
    o_colour = vec4(is_edge ? textureLod(u_display, uv, 0.0).rgb : centre, 1.0);
}
