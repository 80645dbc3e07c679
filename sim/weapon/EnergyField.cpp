#include "sim/weapon/EnergyField.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

namespace sim {

namespace {

struct Parts {
    glm::dvec3 m, d;
    double length, a, b, radius;
};

Parts parts(const EnergySegment& s) {
    return {glm::dvec3(s.start), glm::normalize(glm::dvec3(s.direction)), double(s.length_m),
            double(s.sphere_strength), double(s.beam_strength), double(s.radius_m)};
}

// 7-point Gauss and 15-point Kronrod nodes and weights on [-1, 1].
constexpr double kXk[8] = {0.991455371120812639, 0.949107912342758525, 0.864864423359769073, 0.741531185599394440,
                           0.586087235467691130, 0.405845151377397167, 0.207784955007898468, 0.0};
constexpr double kWk[8] = {0.022935322010529225, 0.063092092629978553, 0.104790010322250184, 0.140653259715525919,
                           0.169004726639267903, 0.190350578064785410, 0.204432940075298892, 0.209482141084727828};
constexpr double kWg[4] = {0.129484966168869693, 0.279705391489276668, 0.381830050505118945, 0.417959183673469388};

template <class F>
double gauss_kronrod(const F& f, double lo, double hi, double tolerance, int depth) {
    const double c = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
    double kronrod = kWk[7] * f(c), gauss = kWg[3] * f(c);
    for (int i = 0; i < 7; ++i) {
        const double x = h * kXk[i];
        const double sum = f(c - x) + f(c + x);
        kronrod += kWk[i] * sum;
        if (i % 2 == 1) gauss += kWg[i / 2] * sum;
    }
    kronrod *= h;
    gauss *= h;
    if (depth >= 40 || std::fabs(kronrod - gauss) <= tolerance) return kronrod;
    return gauss_kronrod(f, lo, c, 0.5 * tolerance, depth + 1) + gauss_kronrod(f, c, hi, 0.5 * tolerance, depth + 1);
}

double distance_to_segment(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b) {
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double f = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + f * ab));
}

}  // namespace

double energy_density(const EnergySegment& segment, const glm::dvec3& p) {
    const Parts s = parts(segment);
    const glm::dvec3 v = p - s.m;
    const double h = glm::dot(v, s.d);
    double r, c;
    if (h < 0.0) {
        r = glm::length(v);
        c = s.a;
    } else if (h > s.length) {
        r = glm::length(v - s.length * s.d);
        c = s.a;
    } else {
        r = glm::length(v - h * s.d);
        c = s.b;
    }
    return r < s.radius ? c * (1.0 / std::max(r, kEnergyCore_m) - 1.0 / s.radius) : 0.0;
}

double energy_density(std::span<const EnergySegment> segments, const glm::dvec3& p) {
    double sum = 0.0;
    for (const EnergySegment& s : segments) sum += energy_density(s, p);
    return sum;
}

double energy_along_ray(std::span<const EnergySegment> segments, const glm::dvec3& eye, const glm::dvec3& direction,
                        double s_end) {
    const glm::dvec3 q = glm::normalize(direction);
    // Split where the integrand has kinks or peaks: the planes between the parts, the
    // closest approaches to the centres, and the entry into and exit from each
    // segment's reach, so each piece is smooth and the quadrature converges fast.
    std::vector<double> cuts = {0.0, s_end};
    auto cut = [&](double s) {
        if (std::isfinite(s) && s > 0.0 && s < s_end) cuts.push_back(s);
    };
    for (const EnergySegment& seg : segments) {
        const Parts s = parts(seg);
        const double k = glm::dot(q, s.d), h0 = glm::dot(eye - s.m, s.d);
        if (std::fabs(k) > 1e-12) {
            cut(-h0 / k);
            cut((s.length - h0) / k);
        }
        for (glm::dvec3 centre : {s.m, s.m + s.length * s.d}) {
            const glm::dvec3 w = eye - centre;
            const double b = glm::dot(q, w);
            cut(-b);
            const double disc = b * b - glm::dot(w, w) + s.radius * s.radius;
            if (disc > 0.0) {
                cut(-b - std::sqrt(disc));
                cut(-b + std::sqrt(disc));
            }
        }
        // Closest approach to the axis line and the entry into and exit from the cylinder.
        const glm::dvec3 w = eye - s.m;
        const glm::dvec3 qp = q - k * s.d, wp = w - h0 * s.d;
        const double A = glm::dot(qp, qp), B = glm::dot(qp, wp), C = glm::dot(wp, wp);
        if (A > 1e-14) {
            cut(-B / A);
            const double disc = B * B - A * (C - s.radius * s.radius);
            if (disc > 0.0) {
                cut((-B - std::sqrt(disc)) / A);
                cut((-B + std::sqrt(disc)) / A);
            }
        }
    }
    std::sort(cuts.begin(), cuts.end());
    auto f = [&](double s) { return energy_density(segments, eye + s * q); };
    double total = 0.0;
    for (size_t i = 0; i + 1 < cuts.size(); ++i)
        if (cuts[i + 1] > cuts[i]) total += gauss_kronrod(f, cuts[i], cuts[i + 1], 1e-11, 0);
    return total;
}

double energy_singular_distance(std::span<const EnergySegment> segments, const glm::dvec3& eye,
                                const glm::dvec3& direction, double s_end) {
    const glm::dvec3 q = glm::normalize(direction);
    const glm::dvec3 end = eye + s_end * q;
    double best = 1e300;
    for (const EnergySegment& seg : segments) {
        const Parts s = parts(seg);
        const glm::dvec3 head = s.m + s.length * s.d;
        // The singular points are the axis from M to the head: sample the ray finely
        // where it passes within the segment's bounding sphere (a reference needs no
        // closed form), and take its ends.
        const glm::dvec3 w = eye - 0.5 * (s.m + head);
        const double b = glm::dot(q, w), reach = 0.5 * s.length + s.radius;
        const double disc = b * b - glm::dot(w, w) + reach * reach;
        best = std::min({best, distance_to_segment(eye, s.m, head), distance_to_segment(end, s.m, head)});
        if (disc <= 0.0) continue;
        const double lo = std::clamp(-b - std::sqrt(disc), 0.0, s_end), hi = std::clamp(-b + std::sqrt(disc), 0.0, s_end);
        for (int i = 0; i <= 4000; ++i)
            best = std::min(best, distance_to_segment(eye + (lo + (hi - lo) * i / 4000.0) * q, s.m, head));
    }
    return best;
}

}  // namespace sim
