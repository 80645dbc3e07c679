#pragma once
// The fluid tank's measurements (docs/effects/fluid.md, "Benchmarks"): the analytic
// quality harness (particles filling a sphere or a box in front of the camera, errors
// against the exact surface) and the bench cases reproducing the seed's tables 5.1-5.4.
// Everything here needs a current GL context.
#include <string>

#include "effects/fluid/FluidSmoothing.h"
#include "game/bench/BenchReport.h"

namespace game {

enum class QualityShape { Sphere, Box };

struct SmoothingQuality {
    double depth_mean_m = 0.0, depth_p95_m = 0.0;  // |reconstructed - exact| front depth
    double silhouette_normal_deg = 0.0;  // mean angle error where the exact normal is > 60 deg from the view
    double interior_normal_deg = 0.0;    // mean angle error elsewhere
    int pixels = 0;                      // compared (covered by both)
};

struct ExitRayQuality {
    double mean_deg = 0.0, p95_deg = 0.0;  // angle between traced and exact exit rays
    int rays = 0;                          // pixels compared
    double converged = 0.0;                // share of them where the secant search converged
};

// The front surface of `shape` reconstructed with `smoothing` at width x height.
SmoothingQuality measure_smoothing(QualityShape shape, const effects::FluidSmoothing& smoothing, int width,
                                   int height);
// The 2-surface secant trace through the sphere (plane fitting) against the exact
// double refraction, over pixels whose exact entry angle is below 45 degrees.
ExitRayQuality measure_exit_rays(int width, int height);

// Adds the "fluid" group's cases; `quick` renders fewer frames and kernel sizes.
void bench_fluid(BenchReport& report, bool quick);

}  // namespace game
