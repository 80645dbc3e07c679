#pragma once
// The objective's cues, heard in the middle, not placed: a gate passed (two rising
// notes), a lap finished (a major arpeggio), a target hit (a bright bell). Notes are
// additive bells: partials at the ratios of a struck bar, decaying exponentially
// (modal synthesis again: van den Doel, Kry and Pai 2001).
#include <array>
#include <vector>

#include "audio/Dsp.h"
#include "audio/Voice.h"

namespace audio {

enum class CueKind { Gate, Lap, Target };

class CueVoice final : public Voice {
public:
    CueVoice(CueKind kind, int delay);
    bool render(float* out, int frames, float pitch) override;

private:
    struct Note {
        int start = 0;  // samples from the cue's start
        float hz = 440.0f;
        float amplitude = 0.2f;
    };
    std::vector<Note> notes_;
    std::vector<std::array<Mode, 3>> modes_;
    int age_ = 0, length_ = 0;
};

}  // namespace audio
