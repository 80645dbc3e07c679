#pragma once
// Real time turned into whole fixed ticks per frame.
#include <chrono>
#include <cstdint>

namespace game {

// Counts in whole nanoseconds times the tick rate, so no rounding drift builds up over
// a long session. A slow frame is made up by running as many ticks as real time needs;
// only more than `max_ticks_per_frame` owed at once (a spiral: ticks making frames slower
// making more ticks due) drops the excess, and then the world runs behind real time.
class FixedStepClock {
public:
    static constexpr double kSpiralCapSeconds = 0.25;

    // The cap defaults to kSpiralCapSeconds of ticks (15 at 60 Hz).
    explicit FixedStepClock(int tick_rate_hz, int max_ticks_per_frame = 0);

    // Adds the real time since the last frame; returns how many ticks to run now.
    int advance(std::chrono::nanoseconds elapsed);
    // Forgets accumulated time, so that a pause is not made up for afterwards.
    void reset() { pending_ = 0; }
    // Time accumulated towards the next tick.
    std::chrono::nanoseconds pending() const { return std::chrono::nanoseconds(pending_ / rate_hz_); }
    // The fraction of a tick pending, in [0, 1): how far real time is past the last tick,
    // to interpolate the world's state between the last two ticks when drawing.
    double alpha() const { return double(pending_) / double(kNsPerSecond); }
    // Real time the last advance() dropped at the cap: the world fell behind by this much.
    std::chrono::nanoseconds dropped() const { return dropped_; }
    int max_ticks_per_frame() const { return max_ticks_; }

private:
    static constexpr int64_t kNsPerSecond = 1'000'000'000;
    int64_t rate_hz_;
    int max_ticks_;
    int64_t pending_ = 0;  // nanoseconds * rate_hz_: a tick is kNsPerSecond of these
    std::chrono::nanoseconds dropped_{0};
};

}  // namespace game
