#include "game/play/ResolutionController.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "game/play/FrameTargets.h"

namespace game {

ResolutionController::ResolutionController(const Options& options) : options_(options) {
    if (!(options.min_scale > 0.0f && options.min_scale <= options.max_scale && options.step > 0.0f &&
          options.budget_ms > 0.0 && options.down_window >= 2 && options.up_frames >= 1 &&
          options.up_share > 0.0 && options.up_share <= 1.0 && options.fixed_share >= 0.0 &&
          options.fixed_share < 1.0))
        throw std::invalid_argument("ResolutionController: bad options");
    scale_ = snap(options.start_scale);
}

float ResolutionController::snap(float scale) const {
    const float steps = std::floor(scale / options_.step + 1e-3f);
    return std::clamp(steps * options_.step, options_.min_scale, options_.max_scale);
}

float ResolutionController::frame(double frame_ms) {
    if (!std::isfinite(frame_ms) || frame_ms < 0.0) return scale_;
    recent_.push_back(frame_ms);
    if (recent_.size() > std::max(options_.down_window, options_.up_frames)) recent_.pop_front();

    float next = scale_;
    if (recent_.size() >= options_.down_window) {
        // The last frames' mean without the worst: one hitch (a resize, a page fault) is no trend.
        const auto last = recent_.end() - std::ptrdiff_t(options_.down_window);
        const double sum = std::accumulate(last, recent_.end(), 0.0);
        const double worst = *std::max_element(last, recent_.end());
        const double typical = (sum - worst) / double(options_.down_window - 1);
        if (typical > options_.budget_ms) {
            // Aim a little under the budget, and always at least one step down.
            const float aim = scale_ * float(std::sqrt(0.9 * options_.budget_ms / typical));
            next = std::min(snap(aim), snap(scale_ - options_.step));
        }
    }
    if (next == scale_ && recent_.size() >= options_.up_frames) {
        const float up = snap(scale_ + options_.step);
        const double pixels = double(up / scale_) * double(up / scale_);
        const double grow = options_.fixed_share + (1.0 - options_.fixed_share) * pixels;
        const double well_under = options_.up_fraction * options_.budget_ms;
        const auto fast = std::count_if(recent_.end() - std::ptrdiff_t(options_.up_frames), recent_.end(),
                                        [&](double ms) { return ms * grow < well_under; });
        if (double(fast) >= options_.up_share * double(options_.up_frames)) next = up;
    }
    if (next != scale_) {
        scale_ = next;
        recent_.clear();
    }
    return scale_;
}

double auto_frame_budget_ms(double fill_ms) {
    constexpr double kPlayableMs = 30.0;
    if (!std::isfinite(fill_ms) || fill_ms <= 0.0) return kPlayableMs;
    return std::min(kAutoMeanFills * fill_ms, kPlayableMs);
}

}  // namespace game
