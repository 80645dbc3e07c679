#include "audio/models/GlassDrops.h"

#include <algorithm>

namespace audio {

namespace {
constexpr size_t kMaxHits = 48;
}

GlassDropsVoice::GlassDropsVoice(uint32_t seed) : Voice(Bus::Effects), rng_(seed * 3266489917u + 7u) {}

void GlassDropsVoice::land(int count, int frames, float level) {
    for (int i = 0; i < count && hits_.size() < kMaxHits; ++i) {
        Hit h;
        h.delay = int(rng_.unit() * float(frames));
        const float a = level * (0.4f + 0.6f * rng_.unit());
        h.drop.strike(rng_.range(2600.0f, 5200.0f), 0.0025f, a);
        h.pane.strike(rng_.range(450.0f, 900.0f), 0.006f, 0.6f * a);
        hits_.push_back(h);
    }
}

bool GlassDropsVoice::render(float* out, int frames, float) {
    for (Hit& h : hits_) {
        int n = std::min(h.delay, frames);
        h.delay -= n;
        for (; n < frames; ++n) out[n] += h.drop.next() + h.pane.next();
    }
    std::erase_if(hits_, [](const Hit& h) { return h.delay == 0 && h.drop.quiet() && h.pane.quiet(); });
    return true;
}

}  // namespace audio
