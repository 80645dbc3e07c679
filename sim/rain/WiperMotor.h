#pragma once
// The wiper motor: one cycle takes the blades out from rest and back with a smooth
// (cosine) speed profile. Low and high run cycles back to back at two speeds,
// intermittent pauses at rest between cycles, off finishes the cycle under way and
// parks.
#include <cstdint>

#include "sim/player/Player.h"

namespace sim {

struct WiperMotorParams {
    float low_cycle_s = 1.6f;
    float high_cycle_s = 0.9f;
    float intermittent_pause_s = 2.5f;
};

class WiperMotor {
public:
    explicit WiperMotor(WiperMotorParams params = {}) : p_(params) {}

    void step(WiperMode mode, float dt);
    // How far out the blades are: 0 at rest, 1 at the far end of the sweep.
    float fraction() const;
    float phase() const { return phase_; }  // 0..1 through the cycle, 0 at rest
    float pause_s() const { return pause_s_; }
    bool parked() const { return phase_ == 0.0f; }
    const WiperMotorParams& params() const { return p_; }

    template <class Archive> void describe(Archive& ar) {
        ar.f32(phase_);
        ar.f32(pause_s_);
    }

private:
    WiperMotorParams p_;
    float phase_ = 0.0f;
    float pause_s_ = 0.0f;  // intermittent: rest left before the next cycle
};

}  // namespace sim
