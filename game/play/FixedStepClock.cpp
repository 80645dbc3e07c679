#include "game/play/FixedStepClock.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace game {

FixedStepClock::FixedStepClock(int tick_rate_hz, int max_ticks_per_frame)
    : rate_hz_(tick_rate_hz),
      max_ticks_(max_ticks_per_frame > 0 ? max_ticks_per_frame
                                         : std::max(1, int(std::lround(kSpiralCapSeconds * tick_rate_hz)))) {
    if (tick_rate_hz < 1 || max_ticks_per_frame < 0)
        throw std::invalid_argument("FixedStepClock needs a tick rate of at least 1 and a tick cap of at least 1");
}

int FixedStepClock::advance(std::chrono::nanoseconds elapsed) {
    // More than a second adds nothing the cap would not drop (the cap is under a
    // second of ticks); the bound keeps the product far from overflow.
    const int64_t ns = std::clamp<int64_t>(elapsed.count(), 0, kNsPerSecond);
    const int64_t over_a_second = std::max<int64_t>(0, elapsed.count() - kNsPerSecond);
    pending_ += ns * rate_hz_;
    const int64_t due = pending_ / kNsPerSecond;
    const int ticks = int(std::min<int64_t>(due, max_ticks_));
    // Behind by more than the cap: drop the whole ticks left rather than owe them.
    const int64_t dropped_ticks = due - ticks;
    pending_ -= (ticks + dropped_ticks) * kNsPerSecond;
    dropped_ = std::chrono::nanoseconds(dropped_ticks * kNsPerSecond / rate_hz_ + over_a_second);
    return ticks;
}

}  // namespace game
