#include "audio/models/ShotHum.h"

#include <cmath>

namespace audio {

ShotHumVoice::ShotHumVoice(uint32_t seed) : Voice(Bus::Effects), noise_(seed * 69069u + 1u) {
    tone_.lowpass(3500.0f, 1.2f);
    place.reference_m = 6.0f;
}

void ShotHumVoice::set(float growth, float brightness, float sway) {
    growth_.set(growth);
    level_.set(brightness);
    sway_.set(sway);
}

bool ShotHumVoice::render(float* out, int frames, float pitch) {
    growth_.begin_block(frames);
    level_.begin_block(frames);
    sway_.begin_block(frames);
    for (int n = 0; n < frames; ++n) {
        const float g = growth_.next(), level = level_.next(), sway = sway_.next();
        // The charge sweeps up 180 -> 520 Hz while the ball grows; then the beam hums.
        const float f = (180.0f + 340.0f * g) * (1.0f + 0.04f * sway) * pitch;
        phase_ += f / float(kSampleRate);
        if (phase_ >= 1.0f) phase_ -= 1.0f;
        phase2_ += f * 1.505f / float(kSampleRate);  // a slightly detuned fifth above beats against it
        if (phase2_ >= 1.0f) phase2_ -= 1.0f;
        const float square = phase_ < 0.5f ? 1.0f : -1.0f;
        const float tri = 4.0f * std::fabs(phase2_ - 0.5f) - 1.0f;
        const float x = tone_.process(0.6f * square + 0.5f * tri + 0.08f * noise_.next());
        out[n] += x * level * 0.1f;
    }
    return !released_ || audible();
}

}  // namespace audio
