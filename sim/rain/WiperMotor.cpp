#include "sim/rain/WiperMotor.h"

#include <cmath>

#include "sim/core/DetMath.h"

namespace sim {

void WiperMotor::step(WiperMode mode, float dt) {
    if (phase_ == 0.0f) {
        if (mode == WiperMode::Off) return;
        if (mode == WiperMode::Intermittent && pause_s_ > 0.0f) {
            pause_s_ -= dt;
            return;
        }
    }
    const float cycle = mode == WiperMode::High ? p_.high_cycle_s : p_.low_cycle_s;
    phase_ += dt / cycle;
    if (phase_ >= 1.0f) {
        phase_ = 0.0f;
        pause_s_ = mode == WiperMode::Intermittent ? p_.intermittent_pause_s : 0.0f;
    }
}

float WiperMotor::fraction() const { return 0.5f - 0.5f * det::cos(6.28318531f * phase_); }

}  // namespace sim
