// The energy field of specs/energy.md and its line integrals along a view ray
// R(s) = S + s q (|q| = 1, s in metres from the eye). Every part of a segment (tail
// sphere, beam, head sphere) is density c/max(r, core) - c/R inside its cut-off radius
// R, so a part's integral over an interval is c * (closed form of 1/max(r, core) - length / R).

struct EnergySegmentGpu {
    vec4 start_sphere;  // M, a
    vec4 dir_length;    // D, L
    vec4 beam_radius;   // b, R, -, -
};
layout(std430, binding = 0) readonly buffer EnergySegments { EnergySegmentGpu u_segments[]; };

// The density is clamped to its value at this distance from a centre or the axis: rays
// through M or along the axis stay finite.
const float kEnergyCore_m = 0.02;

// log(1 + d) for d >= 0, accurate for small d too.
float log1p_small(float d) {
    return d < 1e-2 ? d * (1.0 - d * (0.5 - d * (1.0 / 3.0 - d * 0.25))) : log(1.0 + d);
}

// Integral of du / sqrt(u^2 + m^2) over [p0, p0 + dp], p0 >= 0: log((p1 + r1) / (p0 + r0))
// written as log1p of a ratio, so nothing cancels when the interval is short in u
// (a ray nearly parallel to the axis) and nothing divides by m (a ray through it).
float log_ratio(float p0, float dp, float m) {
    float p1 = p0 + dp;
    float r0 = sqrt(p0 * p0 + m * m), r1 = sqrt(p1 * p1 + m * m);
    return log1p_small(dp * (1.0 + (p1 + p0) / (r1 + r0)) / (p0 + r0));
}

// Integral over [s0, s1] of ds / max(sqrt(A s^2 + 2 B s + C), core), the quadratic being
// the squared distance to a point (A = 1) or an axis, and m = sqrt(A C - B^2) (the
// caller gets it from a cross product, free of cancellation). With u = A s + B the
// distance is sqrt(u^2 + m^2) / sqrt(A), so outside the core the integral is
// asinh(u / m) / sqrt(A), taken on each side of the closest point as a log ratio;
// inside the core (|u| < uc) the density is clamped, a constant.
float line_integral(float A, float B, float C, float m, float s0, float s1) {
    if (!(s1 > s0)) return 0.0;
    if (A < 1e-12) return (s1 - s0) / max(sqrt(C), kEnergyCore_m);  // parallel: constant distance
    float u0 = A * s0 + B, u1 = A * s1 + B;
    float uc = sqrt(max(A * kEnergyCore_m * kEnergyCore_m - m * m, 0.0));
    float logs = 0.0;
    if (u1 > uc) logs += log_ratio(max(u0, uc), u0 >= uc ? A * (s1 - s0) : u1 - uc, m);
    if (u0 < -uc) logs += log_ratio(max(-u1, uc), u1 <= -uc ? A * (s1 - s0) : -uc - u0, m);
    float c0 = max(u0, -uc), c1 = min(u1, uc);
    float core = c1 > c0 ? (c1 - c0) / (A * kEnergyCore_m) : 0.0;
    return logs / sqrt(A) + core;
}

vec2 overlap(vec2 r, vec2 o) { return vec2(max(r.x, o.x), min(r.y, o.y)); }

// Where on [0, s_end] the axial coordinate h0 + k s is at most c (behind the plane
// h = c) or at least c (ahead of it).
vec2 behind_plane(float h0, float k, float c, float s_end) {
    if (abs(k) < 1e-6) return h0 + k * 0.5 * s_end <= c ? vec2(0.0, s_end) : vec2(0.0);
    float s = clamp((c - h0) / k, 0.0, s_end);
    return k > 0.0 ? vec2(0.0, s) : vec2(s, s_end);
}
vec2 ahead_of_plane(float h0, float k, float c, float s_end) {
    if (abs(k) < 1e-6) return h0 + k * 0.5 * s_end >= c ? vec2(0.0, s_end) : vec2(0.0);
    float s = clamp((c - h0) / k, 0.0, s_end);
    return k > 0.0 ? vec2(s, s_end) : vec2(0.0, s);
}

// Within R of a point (A = 1) or an axis: A s^2 + 2 B s + C < R^2.
vec2 within_radius(float A, float B, float C, float m, float R) {
    if (A < 1e-12) return C < R * R ? vec2(-3e38, 3e38) : vec2(0.0);
    float h2 = A * R * R - m * m;
    if (h2 <= 0.0) return vec2(0.0);
    float h = sqrt(h2);
    return vec2((-B - h) / A, (-B + h) / A);
}

// c * integral of (1/r - 1/R) over the part of [r.x, r.y] inside the radius.
float truncated_part(float c, float A, float B, float C, float m, float R, vec2 r) {
    r = overlap(r, within_radius(A, B, C, m, R));
    if (!(r.y > r.x)) return 0.0;
    return c * max(line_integral(A, B, C, m, r.x, r.y) - (r.y - r.x) / R, 0.0);
}

// The closed-form energy of one segment along the ray: tail sphere, beam, head sphere.
float segment_energy(EnergySegmentGpu seg, vec3 S, vec3 q, float s_end) {
    vec3 M = seg.start_sphere.xyz, D = seg.dir_length.xyz;
    float a = seg.start_sphere.w, L = seg.dir_length.w, b = seg.beam_radius.x, R = seg.beam_radius.y;
    vec3 W = S - M;
    float h0 = dot(W, D), k = dot(q, D);
    float e = 0.0;
    // Tail sphere about M, behind the plane I.
    e += truncated_part(a, 1.0, dot(q, W), dot(W, W), length(cross(q, W)), R, behind_plane(h0, k, 0.0, s_end));
    // Head sphere about M + L D, beyond the end plane.
    vec3 W2 = W - L * D;
    e += truncated_part(a, 1.0, dot(q, W2), dot(W2, W2), length(cross(q, W2)), R, ahead_of_plane(h0, k, L, s_end));
    // Beam: distance to the axis in the plane normal to D; A C - B^2 = (D . (q x W))^2.
    vec3 qp = q - k * D, wp = W - h0 * D;
    vec2 slab = overlap(ahead_of_plane(h0, k, 0.0, s_end), behind_plane(h0, k, L, s_end));
    e += truncated_part(b, dot(qp, qp), dot(qp, wp), dot(wp, wp), abs(dot(D, cross(q, W))), R, slab);
    return e;
}

// The density at a point: what the ray-marching baseline samples.
float segment_density(EnergySegmentGpu seg, vec3 P) {
    vec3 M = seg.start_sphere.xyz, D = seg.dir_length.xyz;
    float a = seg.start_sphere.w, L = seg.dir_length.w, b = seg.beam_radius.x, R = seg.beam_radius.y;
    vec3 v = P - M;
    float h = dot(v, D);
    float r, c;
    if (h < 0.0) {
        r = length(v);
        c = a;
    } else if (h > L) {
        r = length(v - L * D);
        c = a;
    } else {
        r = sqrt(max(dot(v, v) - h * h, 0.0));
        c = b;
    }
    return r < R ? c * (1.0 / max(r, kEnergyCore_m) - 1.0 / R) : 0.0;
}

// Where the ray can meet the segment's field at all: its bounding sphere.
vec2 segment_reach(EnergySegmentGpu seg, vec3 S, vec3 q) {
    float L = seg.dir_length.w;
    vec3 centre = seg.start_sphere.xyz + 0.5 * L * seg.dir_length.xyz;
    float radius = 0.5 * L + seg.beam_radius.y;
    vec3 w = S - centre;
    float B = dot(q, w), h2 = B * B - dot(w, w) + radius * radius;
    if (h2 <= 0.0) return vec2(0.0);
    float h = sqrt(h2);
    return vec2(-B - h, -B + h);
}
