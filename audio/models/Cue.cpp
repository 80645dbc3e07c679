#include "audio/models/Cue.h"

namespace audio {

namespace {
int ms(float milliseconds) { return int(milliseconds * 0.001f * float(kSampleRate)); }
}  // namespace

CueVoice::CueVoice(CueKind kind, int delay) : Voice(Bus::Effects) {
    place.positioned = false;
    place.outside = false;
    switch (kind) {
        case CueKind::Gate: notes_ = {{0, 659.3f, 0.12f}, {ms(90), 880.0f, 0.12f}}; break;
        case CueKind::Lap:
            notes_ = {{0, 523.3f, 0.12f}, {ms(110), 659.3f, 0.12f}, {ms(220), 784.0f, 0.12f}, {ms(330), 1046.5f, 0.14f}};
            break;
        case CueKind::Target: notes_ = {{0, 1318.5f, 0.14f}, {ms(60), 1975.5f, 0.10f}}; break;
    }
    for (Note& n : notes_) n.start += delay;
    modes_.resize(notes_.size());
    length_ = notes_.back().start + ms(1500);
}

bool CueVoice::render(float* out, int frames, float) {
    for (size_t i = 0; i < notes_.size(); ++i) {
        const Note& note = notes_[i];
        for (int n = 0; n < frames; ++n) {
            const int t = age_ + n;
            if (t < note.start) continue;
            if (t == note.start) {
                // A struck bar's first partials: 1, 2.76, 5.40 (free-free bar).
                modes_[i][0].strike(note.hz, 0.35f, note.amplitude);
                modes_[i][1].strike(note.hz * 2.76f, 0.12f, note.amplitude * 0.35f);
                modes_[i][2].strike(note.hz * 5.40f, 0.05f, note.amplitude * 0.15f);
            }
            out[n] += modes_[i][0].next() + modes_[i][1].next() + modes_[i][2].next();
        }
    }
    age_ += frames;
    return age_ < length_;
}

}  // namespace audio
