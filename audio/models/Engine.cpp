#include "audio/models/Engine.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace audio {

namespace {
constexpr std::array<float, 6> kRatios{0.0f, 3.5f, 2.1f, 1.45f, 1.1f, 0.86f};  // [0] unused
constexpr float kFinalDrive = 3.9f;
constexpr float kWheelRadius_m = 0.33f;
constexpr float kUpshiftRpm = 4400.0f, kUpshiftFullRpm = 5800.0f, kDownshiftRpm = 1700.0f;
constexpr float kShift_s = 0.22f;
constexpr int kHarmonics = 14;
}  // namespace

float Gearbox::rpm_for(float speed_mps, int gear) const {
    return std::fabs(speed_mps) / kWheelRadius_m * kRatios[size_t(gear)] * kFinalDrive * (60.0f / kTwoPi);
}

void Gearbox::tick(float speed_mps, float throttle, float dt) {
    const float wheel_rpm = rpm_for(speed_mps, gear_);
    if (shift_s_ <= 0.0f) {
        const float up_at = kUpshiftRpm + (kUpshiftFullRpm - kUpshiftRpm) * throttle;
        if (gear_ < 5 && wheel_rpm > up_at) {
            ++gear_;
            shift_s_ = kShift_s;
        } else if (gear_ > 1 && wheel_rpm < kDownshiftRpm) {
            --gear_;
            shift_s_ = kShift_s * 0.7f;
        }
    }
    // In first gear at walking pace the clutch slips: the engine revs on the throttle.
    float target = std::max(rpm_for(speed_mps, gear_), kIdleRpm + throttle * 1500.0f * (gear_ == 1 ? 1.0f : 0.0f));
    target = std::max(target, kIdleRpm);
    // The engine's inertia, and a shift's clutch: the rpm falls to the new gear over the shift.
    const float rate = shift_s_ > 0.0f ? 10.0f : 14.0f;
    rpm_ += (target - rpm_) * std::min(1.0f, rate * dt);
    load_ = shift_s_ > 0.0f ? 0.0f : throttle;
    shift_s_ = std::max(0.0f, shift_s_ - dt);
}

EngineVoice::EngineVoice(Bus bus, EngineSound sound) : Voice(bus), sound_(sound), noise_(sound.seed * 7919u + 17u) {
    formant_.bandpass(sound_.formant_hz, 1.4f);
    hiss_.bandpass(sound_.noise_hz, 0.8f);
    body_.lowpass(2400.0f, 0.7f);
}

void EngineVoice::set(float rpm, float load, float level) {
    rpm_.set(rpm);
    load_.set(load);
    level_.set(level);
}

bool EngineVoice::render(float* out, int frames, float pitch) {
    rpm_.begin_block(frames);
    load_.begin_block(frames);
    level_.begin_block(frames);
    if (!audible()) return true;
    // The block's brightness: the harmonics fall off as 1/k^slope, steeper off load.
    const float load = load_.value();
    const float slope = 1.55f - 0.75f * load;
    std::array<float, kHarmonics> amp{};
    float norm = 0.0f;
    for (int k = 1; k <= kHarmonics; ++k) {
        amp[size_t(k - 1)] = std::pow(float(k), -slope) * (k % 2 == 0 ? 0.7f : 1.0f);
        norm += amp[size_t(k - 1)];
    }
    for (float& a : amp) a /= norm;
    const float nyquist_guard = 0.45f * float(kSampleRate);
    for (int n = 0; n < frames; ++n) {
        const float rpm = rpm_.next();
        const float ld = load_.next();
        const float level = level_.next();
        const float f = firing_hz(rpm) * pitch;
        phase_ += f / float(kSampleRate);
        if (phase_ >= 1.0f) {
            phase_ -= 1.0f;
            jitter_ = 1.0f + 0.12f * noise_.next();  // cycle-to-cycle combustion variation
        }
        // sin(k w) by the Chebyshev recurrence from sin w and cos w.
        const float w = kTwoPi * phase_;
        const float s1 = std::sin(w), c2 = 2.0f * std::cos(w);
        float s_prev = 0.0f, s = s1, tone = 0.0f;
        for (int k = 1; k <= kHarmonics; ++k) {
            if (float(k) * f < nyquist_guard) tone += amp[size_t(k - 1)] * s;
            const float next = c2 * s - s_prev;
            s_prev = s;
            s = next;
        }
        // Each firing pushes a puff of exhaust: noise gated by the cycle's first part.
        const float puff = phase_ < 0.3f ? 1.0f - phase_ / 0.3f : 0.0f;
        const float hiss = hiss_.process(noise_.next()) * puff * (0.25f + 0.9f * ld);
        const float x = tone * jitter_ * 3.0f + formant_.process(tone) * (1.0f + 2.0f * ld) + hiss;
        out[n] += body_.process(x) * level * sound_.gain * (0.55f + 0.45f * ld);
    }
    return true;
}

}  // namespace audio
