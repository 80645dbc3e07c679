#pragma once
// The wipers, from the blades' angles and the glass's water (sim::RainSim): the motor's
// hum while it runs, the rubber's swish on wet glass (noise by blade speed times
// wetness), and on drying glass a squeak, the rubber's stick-slip: a tone in bursts as
// the rubber grips and lets go in stretches (the friction model of "Designing Sound",
// A. Farnell 2010, "Practical: Creaking"). The thunk at each reversal is a StrikeVoice.
// The wetness is the water the blades push (RainSim's particles), not the whole glass:
// drops beyond the sweep never reach the rubber.
#include "audio/Dsp.h"
#include "audio/Voice.h"

namespace audio {

class WipersVoice final : public Voice {
public:
    explicit WipersVoice(uint32_t seed);
    // Once a tick: blade speed 0..1 of the fastest sweep, glass wetness 0..1, motor on.
    void set(float blade_speed, float wetness, bool running);
    // The squeak's level 0..1 for a blade speed and a wetness: where the glass is nearly
    // dry and the blade still moves over it.
    static float squeak_for(float blade_speed, float wetness);
    bool render(float* out, int frames, float pitch) override;
    bool audible() const override { return motor_.target() > 0.0f || motor_.value() > 1e-4f; }

private:
    Smoothed motor_{0.0f, 0.05f}, swish_{0.0f, 0.03f}, squeak_{0.0f, 0.03f};
    Noise noise_;
    Biquad swish_band_, squeak_band_, hum_low_;
    OnePole stick_;
    float hum_phase_ = 0.0f, squeak_phase_ = 0.0f;
    float chatter_ = 0.0f, chatter_target_ = 0.0f;  // the rubber's grip 0..1
    int chatter_left_ = 0;                          // samples until it changes
};

}  // namespace audio
