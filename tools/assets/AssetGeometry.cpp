#include "tools/assets/AssetGeometry.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace assets {

namespace {
constexpr float kPi = glm::pi<float>();
}  // namespace


float hash01(uint32_t x) {  // integer hash (lowbias32) to [0, 1)
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return float(x >> 8) / 16777216.0f;
}
float lattice(int x, int y, int z) { return hash01(uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(z) * 83492791u); }
float value_noise(vec3 p) {  // smooth 3D value noise in [0, 1)
    vec3 f = glm::floor(p), t = p - f;
    t = t * t * (3.0f - 2.0f * t);
    int x = int(f.x), y = int(f.y), z = int(f.z);
    auto lerp = [](float a, float b, float s) { return a + (b - a) * s; };
    float c[2][2];
    for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k) c[j][k] = lerp(lattice(x, y + j, z + k), lattice(x + 1, y + j, z + k), t.x);
    return lerp(lerp(c[0][0], c[1][0], t.y), lerp(c[0][1], c[1][1], t.y), t.z);
}


Xf at(vec3 t, float yaw) {
    return {glm::rotate(glm::translate(mat4(1.0f), t), yaw, vec3(0, 1, 0))};
}
Xf turned(Xf base, float angle, vec3 axis) { return {glm::rotate(base.m, angle, axis)}; }

Shade flat(vec4 c) { return [c](vec3) { return c; }; }


// Convex planar polygon, local points, outward local normal.
void poly(Part& m, const Xf& x, const std::vector<vec3>& pts, vec3 normal, const Shade& s) {
    vec3 n = x.n(normal);
    uint32_t first = uint32_t(m.pos.size());
    for (vec3 p : pts) m.v(x.p(p), n, s(x.p(p)));
    for (uint32_t i = 1; i + 1 < pts.size(); ++i) m.tri(first, first + i, first + i + 1);
}

void box(Part& m, const Xf& x, vec3 lo, vec3 hi, const Shade& s, bool top) {
    auto c = [&](int i) { return vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
    poly(m, x, {c(1), c(3), c(7), c(5)}, {1, 0, 0}, s);
    poly(m, x, {c(0), c(4), c(6), c(2)}, {-1, 0, 0}, s);
    if (top) poly(m, x, {c(2), c(6), c(7), c(3)}, {0, 1, 0}, s);
    poly(m, x, {c(0), c(1), c(5), c(4)}, {0, -1, 0}, s);
    poly(m, x, {c(4), c(5), c(7), c(6)}, {0, 0, 1}, s);
    poly(m, x, {c(0), c(2), c(3), c(1)}, {0, 0, -1}, s);
}

// Convex profile in local xy, extruded from z0 to z1.
void prism(Part& m, const Xf& x, const std::vector<vec2>& profile, float z0, float z1, const Shade& s) {
    std::vector<vec3> back, front;
    vec2 centre(0.0f);
    for (vec2 p : profile) {
        back.emplace_back(p, z0);
        front.emplace_back(p, z1);
        centre += p / float(profile.size());
    }
    poly(m, x, back, {0, 0, -1}, s);
    poly(m, x, front, {0, 0, 1}, s);
    for (size_t i = 0; i < profile.size(); ++i) {
        vec2 a = profile[i], b = profile[(i + 1) % profile.size()];
        vec2 n = glm::normalize(vec2(b.y - a.y, a.x - b.x));
        if (glm::dot(n, a - centre) < 0.0f) n = -n;
        poly(m, x, {vec3(a, z0), vec3(b, z0), vec3(b, z1), vec3(a, z1)}, vec3(n, 0.0f), s);
    }
}

// Cylinder (r0 at y0, r1 at y1: a cone when r1 = 0) about local +y, smooth sides.
void cylinder(Part& m, const Xf& x, float r0, float r1, float y0, float y1, int segments, const Shade& s,
              bool caps) {
    float slope = (r0 - r1) / (y1 - y0);
    for (int i = 0; i < segments; ++i) {
        float a0 = 2.0f * kPi * float(i) / float(segments), a1 = 2.0f * kPi * float(i + 1) / float(segments);
        auto ring = [&](float a, float r, float y) { return vec3(r * std::cos(a), y, r * std::sin(a)); };
        auto normal = [&](float a) { return x.n(glm::normalize(vec3(std::cos(a), slope, std::sin(a)))); };
        float am = r1 > 0.0f ? a1 : 0.5f * (a0 + a1);  // a cone's tip takes the facet's middle
        uint32_t b0 = m.v(x.p(ring(a0, r0, y0)), normal(a0), s(x.p(ring(a0, r0, y0))));
        uint32_t b1 = m.v(x.p(ring(a1, r0, y0)), normal(a1), s(x.p(ring(a1, r0, y0))));
        uint32_t t1 = m.v(x.p(ring(a1, r1, y1)), normal(am), s(x.p(ring(a1, r1, y1))));
        if (r1 > 0.0f) {
            uint32_t t0 = m.v(x.p(ring(a0, r1, y1)), normal(a0), s(x.p(ring(a0, r1, y1))));
            m.quad(b0, b1, t1, t0);
        } else {
            m.tri(b0, b1, t1);
        }
    }
    if (!caps) return;
    for (auto [r, y, up] : {std::tuple{r0, y0, -1.0f}, std::tuple{r1, y1, 1.0f}}) {
        if (r <= 0.0f) continue;
        std::vector<vec3> pts;
        for (int i = 0; i < segments; ++i) {
            float a = 2.0f * kPi * float(i) / float(segments);
            pts.emplace_back(r * std::cos(a), y, r * std::sin(a));
        }
        poly(m, x, pts, {0, up, 0}, s);
    }
}

// Thick ring sector about local +z, angles a0..a1, from z0 to z1: a closed solid.
void ring_sector(Part& m, const Xf& x, float r_in, float r_out, float a0, float a1, float z0, float z1, int steps,
                 const Shade& s) {
    auto at_angle = [](float r, float a, float z) { return vec3(r * std::cos(a), r * std::sin(a), z); };
    for (int i = 0; i < steps; ++i) {
        float b0 = a0 + (a1 - a0) * float(i) / float(steps), b1 = a0 + (a1 - a0) * float(i + 1) / float(steps);
        for (auto [r, out] : {std::pair{r_out, 1.0f}, std::pair{r_in, -1.0f}}) {
            vec3 n0 = x.n(vec3(std::cos(b0), std::sin(b0), 0) * out), n1 = x.n(vec3(std::cos(b1), std::sin(b1), 0) * out);
            vec3 p[4] = {x.p(at_angle(r, b0, z0)), x.p(at_angle(r, b1, z0)), x.p(at_angle(r, b1, z1)), x.p(at_angle(r, b0, z1))};
            m.quad(m.v(p[0], n0, s(p[0])), m.v(p[1], n1, s(p[1])), m.v(p[2], n1, s(p[2])), m.v(p[3], n0, s(p[3])));
        }
        for (auto [z, n] : {std::pair{z0, -1.0f}, std::pair{z1, 1.0f}})
            poly(m, x, {at_angle(r_in, b0, z), at_angle(r_out, b0, z), at_angle(r_out, b1, z), at_angle(r_in, b1, z)},
                 {0, 0, n}, s);
    }
    for (auto [a, side] : {std::pair{a0, -1.0f}, std::pair{a1, 1.0f}})
        poly(m, x, {at_angle(r_in, a, z0), at_angle(r_out, a, z0), at_angle(r_out, a, z1), at_angle(r_in, a, z1)},
             vec3(-std::sin(a), std::cos(a), 0) * side, s);
}

// Corrugated sheet in the local plane z = 0 facing +z, x0..x1 by y0..y1.
void corrugated(Part& m, const Xf& x, float x0, float x1, float y0, float y1, const Shade& s) {
    const float period = 0.25f, amplitude = 0.018f;
    int columns = int(std::ceil((x1 - x0) / (period / 4.0f)));
    uint32_t prev_lo = 0, prev_hi = 0;
    for (int i = 0; i <= columns; ++i) {
        float u = x0 + (x1 - x0) * float(i) / float(columns);
        float w = 2.0f * kPi * (u - x0) / period;
        vec3 n = x.n(glm::normalize(vec3(-amplitude * 2.0f * kPi / period * std::cos(w), 0.0f, 1.0f)));
        vec3 lo = x.p({u, y0, amplitude * std::sin(w)}), hi = x.p({u, y1, amplitude * std::sin(w)});
        uint32_t a = m.v(lo, n, s(lo)), b = m.v(hi, n, s(hi));
        if (i > 0) m.quad(prev_lo, a, b, prev_hi);
        prev_lo = a;
        prev_hi = b;
    }
}

// Smooth surface P(u, v) on [0, 1]^2 in nu x nv quads; normals by finite differences,
// turned away from a point near the model's centre (all our lofts are convex-ish).
void surface(Part& m, const std::function<vec3(float, float)>& P, int nu, int nv, const Shade& s,
             vec3 centre) {
    std::vector<uint32_t> ids;
    for (int i = 0; i <= nu; ++i)
        for (int k = 0; k <= nv; ++k) {
            float u = float(i) / float(nu), v = float(k) / float(nv), e = 1e-3f;
            vec3 p = P(u, v);
            vec3 du = P(std::min(u + e, 1.0f), v) - P(std::max(u - e, 0.0f), v);
            vec3 dv = P(u, std::min(v + e, 1.0f)) - P(u, std::max(v - e, 0.0f));
            vec3 out = p - centre, n = glm::cross(du, dv);
            if (glm::length(n) < 1e-10f) n = out;
            n = glm::normalize(n);
            if (glm::dot(n, out) < 0.0f) n = -n;
            ids.push_back(m.v(p, n, s(p)));
        }
    for (int i = 0; i < nu; ++i)
        for (int k = 0; k < nv; ++k) {
            uint32_t a = ids[size_t(i * (nv + 1) + k)], b = ids[size_t((i + 1) * (nv + 1) + k)];
            m.quad(a, b, b + 1, a + 1);
        }
}

}  // namespace assets
