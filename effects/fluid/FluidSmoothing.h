#pragma once
// How the body's depth maps are smoothed: plane fitting (the seed's method, default),
// the bilateral filter (the seed's baseline) or a narrow-range filter (today's usual
// open-source baseline), with a kernel size and an iteration count.
#include <string>
#include <string_view>

namespace effects {

enum class SmoothingMethod { PlaneFit, Bilateral, NarrowRange };

struct FluidSmoothing {
    static constexpr int kMaxKernel = 15;
    SmoothingMethod method = SmoothingMethod::PlaneFit;
    int kernel_size = 9;  // odd, 3..kMaxKernel
    int iterations = 3;   // 1..64

    // The seed's settings: plane fitting 9x9 x3, bilateral 7x7 x22; narrow range 9x9 x3.
    static FluidSmoothing defaults(SmoothingMethod method);
    // Throws std::invalid_argument naming the field: even or out-of-range kernel, no iterations.
    void validate() const;
};

// "plane_fit", "bilateral", "narrow_range"; throws std::invalid_argument otherwise.
SmoothingMethod smoothing_method(std::string_view name);
std::string_view smoothing_name(SmoothingMethod method);

}  // namespace effects
