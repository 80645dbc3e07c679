#include "effects/fluid/FluidSmoothing.h"

#include <stdexcept>
#include <string>

namespace effects {

FluidSmoothing FluidSmoothing::defaults(SmoothingMethod method) {
    FluidSmoothing s;
    s.method = method;
    if (method == SmoothingMethod::Bilateral) {
        s.kernel_size = 7;
        s.iterations = 22;
    }
    return s;
}

void FluidSmoothing::validate() const {
    if (kernel_size < 3 || kernel_size > kMaxKernel || kernel_size % 2 == 0)
        throw std::invalid_argument("fluid smoothing: kernel_size must be odd, 3.." + std::to_string(kMaxKernel) +
                                    ", got " + std::to_string(kernel_size));
    if (iterations < 1 || iterations > 64)
        throw std::invalid_argument("fluid smoothing: iterations must be 1..64, got " + std::to_string(iterations));
}

SmoothingMethod smoothing_method(std::string_view name) {
    if (name == "plane_fit") return SmoothingMethod::PlaneFit;
    if (name == "bilateral") return SmoothingMethod::Bilateral;
    if (name == "narrow_range") return SmoothingMethod::NarrowRange;
    throw std::invalid_argument("fluid smoothing: unknown method '" + std::string(name) +
                                "' (plane_fit, bilateral or narrow_range)");
}

std::string_view smoothing_name(SmoothingMethod method) {
    switch (method) {
        case SmoothingMethod::PlaneFit: return "plane_fit";
        case SmoothingMethod::Bilateral: return "bilateral";
        case SmoothingMethod::NarrowRange: return "narrow_range";
    }
    return "?";
}

}  // namespace effects
