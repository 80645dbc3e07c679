#include "audio/models/NoiseBed.h"

#include <cmath>

namespace audio {

NoiseBed::NoiseBed(Bus bus, NoiseBand band)
    : Voice(bus), band_(band), pink_(band.seed * 2654435761u + 1u), wander_(band.seed + 99u), high_hz_(band.high_hz) {
    low_cut_.highpass(band_.low_hz, 0.7071f);
    high_cut_.lowpass(band_.high_hz, 0.7071f);
    swell_phase_ = wander_.unit();
}

void NoiseBed::set(float level, float high_hz) {
    level_.set(level);
    if (high_hz > 0.0f && std::fabs(high_hz - high_hz_) > 1.0f) {
        high_hz_ = high_hz;
        high_cut_.lowpass(high_hz_, 0.7071f);
    }
}

bool NoiseBed::render(float* out, int frames, float) {
    level_.begin_block(frames);
    if (!audible()) return true;
    float swell = 1.0f;
    if (band_.swell_hz > 0.0f) {
        // A slow swell whose period wanders a little from one wave to the next.
        swell_phase_ += band_.swell_hz * swell_rate_ * float(frames) / float(kSampleRate);
        if (swell_phase_ >= 1.0f) {
            swell_phase_ -= 1.0f;
            swell_rate_ = 0.7f + 0.6f * wander_.unit();
        }
        swell = 1.0f - band_.swell_depth * 0.5f * (1.0f + std::cos(kTwoPi * swell_phase_));
    }
    for (int n = 0; n < frames; ++n) {
        const float x = high_cut_.process(low_cut_.process(pink_.next()));
        out[n] += x * level_.next() * swell * band_.gain;
    }
    return true;
}

}  // namespace audio
