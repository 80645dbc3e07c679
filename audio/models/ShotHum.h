#pragma once
// The energy shot: while it grows from a ball into a beam (sim::WeaponParams::growth_s)
// a charge whose pitch rises with its growth, then while it flies a hum (a buzz of odd
// harmonics, its pitch swaying with the shot's sway), fading with the shot's
// brightness. Placed at the shot's head each tick. A subtractive-synthesis "sci-fi"
// tone in the manner of Farnell's "Practical: Sci-Fi" (Designing Sound, 2010).
#include "audio/Dsp.h"
#include "audio/Voice.h"

namespace audio {

class ShotHumVoice final : public Voice {
public:
    explicit ShotHumVoice(uint32_t seed);
    // Once a tick: growth 0..1, brightness 0..1 (fades after a hit), sway -1..1.
    void set(float growth, float brightness, float sway);
    // The shot is gone: fade out and end (the mixer then drops it).
    void release() {
        level_.set(0.0f);
        released_ = true;
    }
    bool render(float* out, int frames, float pitch) override;
    bool audible() const override { return level_.target() > 0.0f || level_.value() > 1e-4f; }

private:
    Smoothed growth_{0.0f, 0.02f}, level_{0.0f, 0.02f}, sway_{0.0f, 0.05f};
    Biquad tone_;
    Noise noise_;
    float phase_ = 0.0f, phase2_ = 0.0f;
    bool released_ = false;
};

}  // namespace audio
