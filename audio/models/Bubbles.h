#pragma once
// Bubbles ringing in water, after K. van den Doel, "Physically based models for liquid
// sounds", ACM Transactions on Applied Perception 2(4), 2005: a bubble of radius r rings
// at the Minnaert frequency f0 = 3 / r (Hz, r in m), decays at d = 0.13 / r + 0.0072 r^-1.5
// (1/s), and its pitch rises as it nears the surface, f(t) = f0 (1 + sigma t) with
// sigma = xi d (xi = 0.1). A cloud of them is the sound of drops on the sea and of a
// splash's entrained air.
#include <vector>

#include "audio/Dsp.h"
#include "audio/Voice.h"

namespace audio {

class BubbleVoice final : public Voice {
public:
    BubbleVoice(Bus bus, uint32_t seed);
    // One bubble of radius `radius_m` at `amplitude`, starting `delay` samples from now.
    void add(float radius_m, float amplitude, int delay);
    // Random bubbles at `per_second`, radii log-uniform in [r_min, r_max] (rain on the sea).
    void set_rain(float per_second, float r_min_m, float r_max_m, float amplitude);
    bool render(float* out, int frames, float pitch) override;
    bool audible() const override { return !bubbles_.empty() || rain_per_s_ > 0.0f; }
    bool idle() const { return bubbles_.empty(); }

private:
    struct Bubble {
        float re = 1.0f, im = 0.0f;                    // the phasor; the sound is its imaginary part
        float freq = 0.0f, rise = 0.0f;                // cycles per sample; rise per sample
        float amp = 0.0f, decay = 1.0f;                // per-sample factor
        int delay = 0;
    };
    std::vector<Bubble> bubbles_;
    Noise noise_;
    float rain_per_s_ = 0.0f, r_min_ = 0.001f, r_max_ = 0.003f, rain_amp_ = 0.0f;
};

}  // namespace audio
