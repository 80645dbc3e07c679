#pragma once
// Something struck: a few decaying modes and a burst of filtered noise, the modal
// synthesis of K. van den Doel, P. G. Kry, D. K. Pai, "FoleyAutomatic: physically-based
// sound effects for interactive simulation and animation" (SIGGRAPH 2001). A car's thud
// on a bollard, a wiper's thunk at reversal, a shot's crack on a wall, a raindrop's tick.
#include <array>

#include "audio/Dsp.h"
#include "audio/Voice.h"

namespace audio {

struct StrikeSound {
    struct ModeSpec {
        float hz = 0.0f, decay_s = 0.0f, amplitude = 0.0f;
    };
    std::array<ModeSpec, 4> modes{};
    float noise_amplitude = 0.0f;
    float noise_decay_s = 0.01f;
    float noise_hz = 2000.0f;  // band centre
    float noise_q = 0.7f;
    int delay = 0;             // samples before it starts
    uint32_t seed = 1;
};

class StrikeVoice final : public Voice {
public:
    StrikeVoice(Bus bus, const StrikeSound& sound);
    bool render(float* out, int frames, float pitch) override;

private:
    std::array<Mode, 4> modes_;
    int mode_count_ = 0;
    Noise noise_;
    Biquad band_;
    float noise_amp_, noise_decay_;
    int delay_;
    int age_ = 0, length_;
};

}  // namespace audio
