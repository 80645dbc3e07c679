#pragma once
// The energy field of a set of segments (see EnergySegment.h) evaluated directly, in
// double precision: the density at a point and its integral along a ray by adaptive
// Gauss-Kronrod quadrature. It is the independent reference the renderer's closed form
// is checked and benchmarked against; the game itself never needs it.
#include <span>

#include <glm/vec3.hpp>

#include "sim/weapon/EnergySegment.h"

namespace sim {

// Below this distance from a centre or an axis the density is clamped (the renderer's
// kEnergyCore_m): the field's only singular points.
inline constexpr double kEnergyCore_m = 0.02;

double energy_density(const EnergySegment& segment, const glm::dvec3& p);
double energy_density(std::span<const EnergySegment> segments, const glm::dvec3& p);

// H: the integral of the density along S + s q for s in [0, s_end] (q is normalised
// here), to a relative accuracy of about 1e-9.
double energy_along_ray(std::span<const EnergySegment> segments, const glm::dvec3& eye, const glm::dvec3& direction,
                        double s_end);

// The smallest distance from the ray's segment [0, s_end] to any segment's centre
// points or axis: how close the ray comes to the field's singular points.
double energy_singular_distance(std::span<const EnergySegment> segments, const glm::dvec3& eye,
                                const glm::dvec3& direction, double s_end);

}  // namespace sim
