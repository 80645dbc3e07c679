// The energy field of docs/effects/energy.md and its line integrals along a view ray
// R(s) = S + s q (|q| = 1, s in metres from the eye). Every part of a segment (tail
// sphere, beam, head sphere) is density c/max(r, core) - c/R inside its cut-off radius
// R, so a part's integral over an interval is c * (closed form of 1/max(r, core) - length / R).
// The eye is the same for every pixel, so what depends only on the eye and the segment
// comes per segment from the CPU (EnergyPass), in double there, and a pixel does only
// what its ray direction changes.

struct EnergySegmentGpu {
    vec4 eye_sphere;    // W = S - M, a
    vec4 dir_length;    // D, L
    vec4 across_beam;   // W - (W.D) D: the eye's offset from the axis, b
    vec4 normal_radius; // W x D, R
    vec4 axial;         // W.D, |W - (W.D) D| (the eye's distance from the axis), -, -
};
layout(std430, binding = 0) readonly buffer EnergySegments { EnergySegmentGpu u_segments[]; };

// The density is clamped to its value at this distance from a centre or the axis: rays
// through M or along the axis stay finite.
const float kEnergyCore_m = 0.02;

// log(1 + d) for d >= 0, accurate for small d too.
float log1p_small(float d) {
    return d < 1e-2 ? d * (1.0 - d * (0.5 - d * (1.0 / 3.0 - d * 0.25))) : log(1.0 + d);
}

// x with log(1 + x) = log((p1 + r1) / (p0 + r0)), the integral of du / sqrt(u^2 + m^2)
// over [p0, p0 + dp], p0 >= 0, r = sqrt(p^2 + m^2): nothing cancels when the interval
// is short in u (a ray nearly parallel to the axis) and nothing divides by m (a ray
// through it).
float log_ratio_arg(float p0, float r0, float dp, float p1, float r1) {
    return dp * ((r1 + r0) + (p1 + p0)) / ((p0 + r0) * (r1 + r0));
}

// Integral over [s0, s1] (inside the cut-off radius) of ds / max(sqrt(A s^2 + 2 B s + C),
// core) - ds / R, the quadratic being the squared distance to a point (A = 1) or an axis,
// m = sqrt(A C - B^2) (the caller gets it from a cross product, free of cancellation),
// as log(1 + x) (returned in .x, to be summed across parts as log1p) plus the rest (.y),
// both to be scaled by 1 / sqrt(A) and c by the caller. With u = A s + B the distance is
// sqrt(u^2 + m^2) / sqrt(A): outside the core the integral is asinh(u / m) / sqrt(A),
// taken on each side of the closest point as a log ratio; inside the core (|u| < uc)
// the density is clamped, a constant. The two sides share their square roots.
vec2 line_integral(float A, float sqrt_A, float B, float m, float inv_R, float s0, float s1) {
    if (!(s1 > s0)) return vec2(0.0);
    float u0 = A * s0 + B, u1 = A * s1 + B;
    float uc = sqrt(max(A * kEnergyCore_m * kEnergyCore_m - m * m, 0.0));
    float r0 = sqrt(u0 * u0 + m * m), r1 = sqrt(u1 * u1 + m * m);
    float rc = max(sqrt_A * kEnergyCore_m, m);  // sqrt(uc^2 + m^2)
    // Each side starts at the interval's end or the core's edge, whichever is further out
    // (the arguments are picked first: both sides of a branch may run).
    bool whole_ahead = u0 >= uc, whole_behind = u1 <= -uc;
    float x = log_ratio_arg(whole_ahead ? u0 : uc, whole_ahead ? r0 : rc, whole_ahead ? A * (s1 - s0) : u1 - uc, u1, r1);
    float y = log_ratio_arg(whole_behind ? -u1 : uc, whole_behind ? r1 : rc, whole_behind ? A * (s1 - s0) : -uc - u0,
                            -u0, r0);
    x = u1 > uc ? x : 0.0;
    y = u0 < -uc ? y : 0.0;
    float c0 = max(u0, -uc), c1 = min(u1, uc);
    float core = c1 > c0 ? (c1 - c0) / (sqrt_A * kEnergyCore_m) : 0.0;
    return vec2(x + y + x * y, core - sqrt_A * (s1 - s0) * inv_R);
}

// The part of [s0, s1] within R of a point (A = 1) or an axis: A s^2 + 2 B s + C < R^2.
vec2 within_radius(float A, float inv_A, float B, float m, float R, float s0, float s1) {
    float h = sqrt(max(A * R * R - m * m, 0.0));
    return vec2(max(s0, (-B - h) * inv_A), min(s1, (-B + h) * inv_A));
}

// The closed-form energy of one segment along the ray: tail sphere, beam, head sphere.
float segment_energy(EnergySegmentGpu seg, vec3 q, float s_end) {
    vec3 W = seg.eye_sphere.xyz, D = seg.dir_length.xyz;
    float a = seg.eye_sphere.w, L = seg.dir_length.w, b = seg.across_beam.w, R = seg.normal_radius.w;
    float h0 = seg.axial.x;
    float k = dot(q, D), qW = dot(q, W);
    vec3 qxW = cross(q, W), qxD = cross(q, D);

    // Where the ray crosses the start plane I (h = 0) and the end plane (h = L), h being
    // the axial coordinate h0 + k s; a ray parallel to them is on one side throughout.
    vec2 tail, beam, head;
    if (abs(k) < 1e-6) {
        float h = h0 + k * 0.5 * s_end;
        tail = h <= 0.0 ? vec2(0.0, s_end) : vec2(0.0);
        head = h >= L ? vec2(0.0, s_end) : vec2(0.0);
        beam = h >= 0.0 && h <= L ? vec2(0.0, s_end) : vec2(0.0);
    } else {
        float inv_k = 1.0 / k;
        float sI = clamp(-h0 * inv_k, 0.0, s_end), sL = clamp((L - h0) * inv_k, 0.0, s_end);
        tail = k > 0.0 ? vec2(0.0, sI) : vec2(sI, s_end);
        head = k > 0.0 ? vec2(sL, s_end) : vec2(0.0, sL);
        beam = k > 0.0 ? vec2(sI, sL) : vec2(sL, sI);
    }
    // Tail sphere about M (B = q.W), head sphere about M + L D (B = q.W - L k).
    float m_tail = length(qxW), m_head = length(qxW - L * qxD);
    float inv_R = 1.0 / R;
    tail = within_radius(1.0, 1.0, qW, m_tail, R, tail.x, tail.y);
    head = within_radius(1.0, 1.0, qW - L * k, m_head, R, head.x, head.y);
    vec2 spheres = line_integral(1.0, 1.0, qW, m_tail, inv_R, tail.x, tail.y);
    vec2 e_head = line_integral(1.0, 1.0, qW - L * k, m_head, inv_R, head.x, head.y);
    float x = spheres.x + e_head.x + spheres.x * e_head.x;
    float e = a * max(log1p_small(x) + spheres.y + e_head.y, 0.0);

    // Beam: distance to the axis, A = |q x D|^2, B = q.(W - h0 D), A C - B^2 = (q.(W x D))^2.
    float A = dot(qxD, qxD), m = abs(dot(q, seg.normal_radius.xyz));
    if (A < 1e-12) {  // parallel to the axis: a constant distance
        float r = seg.axial.y;
        float len = r < R ? max(beam.y - beam.x, 0.0) : 0.0;
        return e + b * len * max(1.0 / max(r, kEnergyCore_m) - inv_R, 0.0);
    }
    float Bb = dot(q, seg.across_beam.xyz), sqrt_A = sqrt(A);
    beam = within_radius(A, 1.0 / A, Bb, m, R, beam.x, beam.y);
    vec2 e_beam = line_integral(A, sqrt_A, Bb, m, inv_R, beam.x, beam.y);
    return e + b * max((log1p_small(e_beam.x) + e_beam.y) / sqrt_A, 0.0);
}

// The density at s along the ray: what the ray-marching baseline samples.
float segment_density(EnergySegmentGpu seg, vec3 q, float s) {
    vec3 D = seg.dir_length.xyz;
    float a = seg.eye_sphere.w, L = seg.dir_length.w, b = seg.across_beam.w, R = seg.normal_radius.w;
    vec3 v = seg.eye_sphere.xyz + s * q;  // P - M
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
vec2 segment_reach(EnergySegmentGpu seg, vec3 q) {
    float L = seg.dir_length.w;
    vec3 w = seg.eye_sphere.xyz - 0.5 * L * seg.dir_length.xyz;  // S - centre
    float radius = 0.5 * L + seg.normal_radius.w;
    float B = dot(q, w), h2 = B * B - dot(w, w) + radius * radius;
    if (h2 <= 0.0) return vec2(0.0);
    float h = sqrt(h2);
    return vec2(-B - h, -B + h);
}
