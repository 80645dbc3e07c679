#pragma once
// Raindrops reaching the windshield (sim::TickReport::glass_drops): each a tick on the
// glass, two short modes (the drop's impact and the pane's ring) struck at a random
// moment within the tick, as in the modal model of van den Doel, Kry and Pai (2001).
// Heard through the glass in the cabin, so not muffled there.
#include <vector>

#include "audio/Dsp.h"
#include "audio/Voice.h"

namespace audio {

class GlassDropsVoice final : public Voice {
public:
    explicit GlassDropsVoice(uint32_t seed);
    // `count` drops land over the next `frames` samples at `level`.
    void land(int count, int frames, float level);
    bool render(float* out, int frames, float pitch) override;
    bool audible() const override { return !hits_.empty(); }

private:
    struct Hit {
        int delay = 0;
        Mode drop, pane;
    };
    std::vector<Hit> hits_;
    Noise rng_;
};

}  // namespace audio
