#include "audio/models/Wipers.h"

#include <algorithm>
#include <cmath>

namespace audio {

WipersVoice::WipersVoice(uint32_t seed) : Voice(Bus::Effects), noise_(seed * 1103515245u + 12345u) {
    swish_band_.bandpass(2000.0f, 0.9f);
    squeak_band_.bandpass(1150.0f, 6.0f);
    hum_low_.lowpass(700.0f, 0.7f);
    stick_.set_cutoff(25.0f);
}

void WipersVoice::set(float blade_speed, float wetness, bool running) {
    motor_.set(running ? 0.35f + 0.65f * blade_speed : 0.0f);
    swish_.set(blade_speed * std::clamp(wetness, 0.0f, 1.0f));
    squeak_.set(squeak_for(blade_speed, wetness));
}

float WipersVoice::squeak_for(float blade_speed, float wetness) {
    const float dry = std::clamp((0.35f - wetness) / 0.3f, 0.0f, 1.0f);
    return blade_speed > 0.05f ? dry * std::min(1.0f, blade_speed * 1.5f) : 0.0f;
}

bool WipersVoice::render(float* out, int frames, float) {
    motor_.begin_block(frames);
    swish_.begin_block(frames);
    squeak_.begin_block(frames);
    if (!audible()) return true;
    for (int n = 0; n < frames; ++n) {
        const float motor = motor_.next(), swish = swish_.next(), squeak = squeak_.next();
        // The motor: a geared whine at 95 Hz, buzzy, under the dashboard.
        hum_phase_ += 95.0f / float(kSampleRate);
        if (hum_phase_ >= 1.0f) hum_phase_ -= 1.0f;
        const float saw = 2.0f * hum_phase_ - 1.0f;
        float x = hum_low_.process(saw) * motor * 0.08f;
        const float white = noise_.next();
        x += swish_band_.process(white) * swish * 0.5f;
        // Stick-slip: the rubber grips and lets go in stretches of 20-80 ms; while it
        // chatters the squeak sounds, its pitch rising with the grip.
        if (--chatter_left_ <= 0) {
            chatter_target_ = noise_.unit();
            chatter_left_ = int((0.02f + 0.06f * noise_.unit()) * float(kSampleRate));
        }
        chatter_ = stick_.lowpass(chatter_target_);
        squeak_phase_ += (1150.0f + 220.0f * chatter_) / float(kSampleRate);
        if (squeak_phase_ >= 1.0f) squeak_phase_ -= 1.0f;
        const float burst = std::max(0.0f, chatter_ - 0.35f) * 1.6f;
        x += squeak_band_.process(2.0f * squeak_phase_ - 1.0f) * burst * squeak * 0.6f;
        out[n] += x;
    }
    return true;
}

}  // namespace audio
