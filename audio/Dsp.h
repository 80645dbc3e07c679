#pragma once
// The few signal-processing pieces every sound model uses. Plain float arithmetic, no
// libm calls in per-sample loops where a recurrence will do, no state shared between
// voices: a render depends only on the sim's ticks (two renders are bit-identical).
#include <cmath>
#include <cstdint>

namespace audio {

inline constexpr int kSampleRate = 48000;
inline constexpr float kPi = 3.14159265f;
inline constexpr float kTwoPi = 6.28318531f;

// White noise in [-1, 1): xorshift32, seeded per voice so every render is the same.
class Noise {
public:
    explicit Noise(uint32_t seed = 0x9e3779b9u) : state_(seed ? seed : 1u) {}
    float next() {
        state_ ^= state_ << 13;
        state_ ^= state_ >> 17;
        state_ ^= state_ << 5;
        return float(int32_t(state_)) * (1.0f / 2147483648.0f);
    }
    // Uniform in [0, 1).
    float unit() { return 0.5f * next() + 0.5f; }
    float range(float lo, float hi) { return lo + (hi - lo) * unit(); }

private:
    uint32_t state_;
};

// Pink-ish noise: Paul Kellet's economy three-pole filter of white noise.
class PinkNoise {
public:
    explicit PinkNoise(uint32_t seed) : white_(seed) {}
    float next() {
        const float w = white_.next();
        b0_ = 0.99765f * b0_ + w * 0.0990460f;
        b1_ = 0.96300f * b1_ + w * 0.2965164f;
        b2_ = 0.57000f * b2_ + w * 1.0526913f;
        return (b0_ + b1_ + b2_ + w * 0.1848f) * 0.25f;
    }

private:
    Noise white_;
    float b0_ = 0.0f, b1_ = 0.0f, b2_ = 0.0f;
};

// y += a (x - y): a first-order low-pass.
class OnePole {
public:
    void set_cutoff(float hz) { a_ = 1.0f - std::exp(-kTwoPi * hz / float(kSampleRate)); }
    float lowpass(float x) { return y_ += a_ * (x - y_); }
    float highpass(float x) { return x - lowpass(x); }
    void reset(float y = 0.0f) { y_ = y; }

private:
    float a_ = 1.0f, y_ = 0.0f;
};

// A second-order section from R. Bristow-Johnson's "Audio EQ Cookbook".
class Biquad {
public:
    void lowpass(float hz, float q) { design(hz, q, Kind::Low); }
    void highpass(float hz, float q) { design(hz, q, Kind::High); }
    void bandpass(float hz, float q) { design(hz, q, Kind::Band); }  // 0 dB peak gain
    float process(float x) {
        const float y = b0_ * x + z1_;
        z1_ = b1_ * x - a1_ * y + z2_;
        z2_ = b2_ * x - a2_ * y;
        return y;
    }

private:
    enum class Kind { Low, High, Band };
    void design(float hz, float q, Kind kind) {
        const float w = kTwoPi * std::fmin(hz, 0.45f * float(kSampleRate)) / float(kSampleRate);
        const float c = std::cos(w), alpha = std::sin(w) / (2.0f * q);
        const float a0 = 1.0f + alpha;
        switch (kind) {
            case Kind::Low: b0_ = b2_ = (1.0f - c) * 0.5f / a0; b1_ = (1.0f - c) / a0; break;
            case Kind::High: b0_ = b2_ = (1.0f + c) * 0.5f / a0; b1_ = -(1.0f + c) / a0; break;
            case Kind::Band: b0_ = alpha / a0; b1_ = 0.0f; b2_ = -alpha / a0; break;
        }
        a1_ = -2.0f * c / a0;
        a2_ = (1.0f - alpha) / a0;
    }
    float b0_ = 1.0f, b1_ = 0.0f, b2_ = 0.0f, a1_ = 0.0f, a2_ = 0.0f;
    float z1_ = 0.0f, z2_ = 0.0f;
};

// A control value set once a tick and heard without steps: once a block it moves a
// fraction of the way to its target (time constant `tau_s`), and within the block the
// samples ramp linearly from the old value to the new one.
class Smoothed {
public:
    explicit Smoothed(float value = 0.0f, float tau_s = 0.03f) : from_(value), to_(value), target_(value), tau_s_(tau_s) {}
    void set(float target) { target_ = target; }
    void jump(float value) { from_ = to_ = target_ = value; }
    void begin_block(int frames) {
        from_ = to_;
        const float k = 1.0f - std::exp(-float(frames) / (tau_s_ * float(kSampleRate)));
        to_ = from_ + (target_ - from_) * k;
        if (std::fabs(to_ - target_) < 1e-6f) to_ = target_;
        step_ = (to_ - from_) / float(frames);
        at_ = from_;
    }
    // The next sample's value within the block.
    float next() { return at_ += step_; }
    float value() const { return to_; }
    float target() const { return target_; }

private:
    float from_, to_, target_, tau_s_;
    float step_ = 0.0f, at_ = 0.0f;
};

// A decaying sinusoid, the mode of a struck object: y[n] = 2 r cos(w) y[n-1] - r^2 y[n-2].
class Mode {
public:
    void strike(float hz, float decay_s, float amplitude) {
        const float w = kTwoPi * hz / float(kSampleRate);
        r_ = std::exp(-1.0f / (decay_s * float(kSampleRate)));
        c_ = 2.0f * r_ * std::cos(w);
        y1_ = 0.0f;                               // y[0] = A sin(0)
        y2_ = -amplitude * std::sin(w) / r_;      // y[-1] = A r^-1 sin(-w)
    }
    float next() {
        const float y = c_ * y1_ - r_ * r_ * y2_;
        y2_ = y1_;
        y1_ = y;
        return y;
    }
    bool quiet() const { return std::fabs(y1_) + std::fabs(y2_) < 1e-5f; }

private:
    float r_ = 0.0f, c_ = 0.0f, y1_ = 0.0f, y2_ = 0.0f;
};

// Linear amplitude from decibels.
inline float db(float decibels) { return std::pow(10.0f, decibels / 20.0f); }

}  // namespace audio
