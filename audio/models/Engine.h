#pragma once
// A combustion engine heard from outside: the firing frequency's harmonics with a
// spectrum that brightens with load, the exhaust's pulse-synchronous noise, and a
// slight cycle-to-cycle jitter. After A. Farnell, "Designing Sound" (MIT Press 2010),
// "Practical 24: Engines" (additive firing harmonics and modulated noise), and S. Baldan,
// H. Lachambre, S. Delle Monache, P. Boussard, "Physically informed car engine sound
// synthesis for virtual and augmented environments" (IEEE SIVE 2015): firing rate =
// rpm / 60 * cylinders / 2 for a four-stroke.
#include "audio/Dsp.h"
#include "audio/Voice.h"

namespace audio {

struct EngineSound {
    float cylinders = 4.0f;
    float strokes = 4.0f;
    float formant_hz = 380.0f;     // the exhaust's resonance
    float noise_hz = 1800.0f;      // centre of the exhaust hiss
    float gain = 0.5f;
    uint32_t seed = 1;
};

class EngineVoice final : public Voice {
public:
    EngineVoice(Bus bus, EngineSound sound);
    // Once a tick: crankshaft speed, load 0 (coasting) .. 1 (full throttle), level.
    void set(float rpm, float load, float level);
    bool render(float* out, int frames, float pitch) override;
    bool audible() const override { return level_.target() > 0.0f || level_.value() > 1e-4f; }
    float firing_hz(float rpm) const { return rpm / 60.0f * sound_.cylinders / (sound_.strokes * 0.5f); }

private:
    EngineSound sound_;
    Smoothed rpm_{800.0f, 0.04f}, load_{0.0f, 0.06f}, level_{0.0f, 0.05f};
    float phase_ = 0.0f;  // of the firing cycle, 0..1
    float jitter_ = 1.0f; // this cycle's strength
    Noise noise_;
    Biquad formant_, hiss_, body_;
};

// The automatic gearbox the engine sound hears through: the rpm follows from the
// driven wheels' speed in the current gear, an upshift comes near the red line (later
// under full throttle), a downshift when the engine labours, and a shift cuts the load
// for a moment (the drop and the pause are what make it audible). Pure function of the
// ticks it is given: deterministic.
class Gearbox {
public:
    static constexpr float kIdleRpm = 850.0f;
    // One tick: the car's speed along itself (m/s), the throttle 0..1.
    void tick(float speed_mps, float throttle, float dt);
    float rpm() const { return rpm_; }
    float load() const { return load_; }
    int gear() const { return gear_; }
    bool shifting() const { return shift_s_ > 0.0f; }

private:
    float rpm_for(float speed_mps, int gear) const;
    int gear_ = 1;
    float rpm_ = kIdleRpm;
    float load_ = 0.0f;
    float shift_s_ = 0.0f;
};

}  // namespace audio
