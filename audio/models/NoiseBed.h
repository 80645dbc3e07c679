#pragma once
// A band of noise at a level set once a tick: the rain's bed, the wind, the sea, the
// tyres' hiss, the bow's spray. Band-limited pink noise with an optional slow swell
// (the sea's waves arriving, the wind's gusts), a common building block of the
// "Designing Sound" practicals (A. Farnell, MIT Press 2010: "Rain", "Wind", "Water").
#include "audio/Dsp.h"
#include "audio/Voice.h"

namespace audio {

struct NoiseBand {
    float low_hz = 200.0f;     // high-pass corner
    float high_hz = 6000.0f;   // low-pass corner
    float swell_hz = 0.0f;     // 0: steady
    float swell_depth = 0.0f;  // 0..1 of the level
    float gain = 0.3f;
    uint32_t seed = 1;
};

class NoiseBed final : public Voice {
public:
    NoiseBed(Bus bus, NoiseBand band);
    // Once a tick: level 0..1, and the band's upper corner (brighter for wet tyres, say; 0 keeps it).
    void set(float level, float high_hz = 0.0f);
    bool render(float* out, int frames, float pitch) override;
    bool audible() const override { return level_.target() > 0.0f || level_.value() > 1e-4f; }
    float level() const { return level_.target(); }

private:
    NoiseBand band_;
    PinkNoise pink_;
    Noise wander_;
    Biquad low_cut_, high_cut_;
    Smoothed level_{0.0f, 0.12f};
    float high_hz_;
    float swell_phase_ = 0.0f, swell_rate_ = 1.0f;
};

}  // namespace audio
