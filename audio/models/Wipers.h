#pragma once
// The wipers, from the blades' angles and the glass's water (sim::RainSim): the motor's
// hum while it runs, the rubber's swish on wet glass (noise by blade speed times
// wetness), and on drying glass a squeak, the rubber's stick-slip: a tone whose bursts
// follow a random stick-slip envelope (the friction model of "Designing Sound",
// A. Farnell 2010, "Practical: Creaking"). The thunk at each reversal is a StrikeVoice.
#include "audio/Dsp.h"
#include "audio/Voice.h"

namespace audio {

class WipersVoice final : public Voice {
public:
    explicit WipersVoice(uint32_t seed);
    // Once a tick: blade speed 0..1 of the fastest sweep, glass wetness 0..1, motor on.
    void set(float blade_speed, float wetness, bool running);
    bool render(float* out, int frames, float pitch) override;
    bool audible() const override { return motor_.target() > 0.0f || motor_.value() > 1e-4f; }

private:
    Smoothed motor_{0.0f, 0.05f}, swish_{0.0f, 0.03f}, squeak_{0.0f, 0.03f};
    Noise noise_;
    Biquad swish_band_, squeak_band_, hum_low_;
    OnePole stick_;
    float hum_phase_ = 0.0f, squeak_phase_ = 0.0f;
};

}  // namespace audio
