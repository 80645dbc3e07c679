#include "audio/models/Strike.h"

#include <algorithm>
#include <cmath>

namespace audio {

StrikeVoice::StrikeVoice(Bus bus, const StrikeSound& s)
    : Voice(bus),
      noise_(s.seed * 2246822519u + 5u),
      noise_amp_(s.noise_amplitude),
      noise_decay_(std::exp(-1.0f / (std::max(s.noise_decay_s, 1e-4f) * float(kSampleRate)))),
      delay_(s.delay) {
    float longest = s.noise_decay_s;
    for (const StrikeSound::ModeSpec& m : s.modes) {
        if (m.amplitude <= 0.0f || m.hz <= 0.0f || m.hz > 0.45f * float(kSampleRate)) continue;
        modes_[size_t(mode_count_++)].strike(m.hz, m.decay_s, m.amplitude);
        longest = std::max(longest, m.decay_s);
    }
    band_.bandpass(s.noise_hz, s.noise_q);
    length_ = int(longest * 9.0f * float(kSampleRate));  // about -80 dB
}

bool StrikeVoice::render(float* out, int frames, float) {
    int n = 0;
    if (delay_ >= frames) {
        delay_ -= frames;
        return true;
    }
    n = delay_;
    delay_ = 0;
    for (; n < frames; ++n) {
        float x = 0.0f;
        for (int m = 0; m < mode_count_; ++m) x += modes_[size_t(m)].next();
        if (noise_amp_ > 1e-5f) {
            x += band_.process(noise_.next()) * noise_amp_;
            noise_amp_ *= noise_decay_;
        }
        out[n] += x;
    }
    age_ += frames;
    return age_ < length_;
}

}  // namespace audio
