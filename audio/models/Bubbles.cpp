#include "audio/models/Bubbles.h"

#include <algorithm>
#include <cmath>

namespace audio {

namespace {
constexpr size_t kMaxBubbles = 96;
constexpr float kXi = 0.1f;
}  // namespace

BubbleVoice::BubbleVoice(Bus bus, uint32_t seed) : Voice(bus), noise_(seed * 40503u + 3u) {}

void BubbleVoice::add(float radius_m, float amplitude, int delay) {
    if (bubbles_.size() >= kMaxBubbles) return;  // a crowd: the oldest are still ringing
    const float f0 = 3.0f / radius_m;
    if (f0 > 0.45f * float(kSampleRate)) return;
    const float d = 0.13f / radius_m + 0.0072f * std::pow(radius_m, -1.5f);
    Bubble b;
    b.freq = f0 / float(kSampleRate);
    b.rise = b.freq * kXi * d / float(kSampleRate);
    b.decay = std::exp(-d / float(kSampleRate));
    b.amp = amplitude;
    b.delay = delay;
    bubbles_.push_back(b);
}

void BubbleVoice::set_rain(float per_second, float r_min_m, float r_max_m, float amplitude) {
    rain_per_s_ = per_second;
    r_min_ = r_min_m;
    r_max_ = r_max_m;
    rain_amp_ = amplitude;
}

bool BubbleVoice::render(float* out, int frames, float pitch) {
    if (rain_per_s_ > 0.0f) {
        // Poisson arrivals over the block, each at its own sample.
        const float expected = rain_per_s_ * float(frames) / float(kSampleRate);
        int count = int(expected);
        if (noise_.unit() < expected - float(count)) ++count;
        const float log_span = std::log(r_max_ / r_min_);
        for (int i = 0; i < count; ++i) {
            const float r = r_min_ * std::exp(log_span * noise_.unit());
            // Smaller bubbles are quieter (van den Doel's amplitude grows with radius).
            add(r, rain_amp_ * (r / r_max_) * (0.4f + 0.6f * noise_.unit()), int(noise_.unit() * float(frames)));
        }
    }
    for (Bubble& b : bubbles_) {
        int n = 0;
        if (b.delay >= frames) {
            b.delay -= frames;
            continue;
        }
        n = b.delay;
        b.delay = 0;
        // The phasor turns by a step recomputed every 32 samples as the pitch rises.
        while (n < frames) {
            const int end = std::min(frames, n + 32);
            const float w = kTwoPi * b.freq * pitch;
            const float cw = std::cos(w), sw = std::sin(w);
            for (; n < end; ++n) {
                const float re = b.re * cw - b.im * sw;
                b.im = b.re * sw + b.im * cw;
                b.re = re;
                out[n] += b.amp * b.im;
                b.amp *= b.decay;
            }
            b.freq += b.rise * 32.0f;
            const float norm = 1.0f / std::sqrt(b.re * b.re + b.im * b.im);
            b.re *= norm;
            b.im *= norm;
        }
    }
    std::erase_if(bubbles_, [](const Bubble& b) { return b.delay == 0 && b.amp < 1e-4f; });
    return true;
}

}  // namespace audio
