#include "audio/models/Splash.h"

#include <algorithm>
#include <cmath>

#include "audio/models/Bubbles.h"
#include "audio/models/Strike.h"

namespace audio {

void play_splash(MixChanges& mix, const SplashCause& cause, glm::vec3 position, uint32_t seed, int delay) {
    Noise rng(seed * 747796405u + 1u);
    const float energy_j = 0.5f * cause.mass_kg * cause.speed_mps * cause.speed_mps;
    // Loudness by the entry's energy, compressed: a pebble is heard, a stone is not deafening.
    const float level = std::clamp(0.25f + 0.2f * std::log10(1.0f + energy_j / 20.0f), 0.2f, 1.0f);
    const float size = std::clamp(cause.radius_m / 0.3f, 0.1f, 2.0f);
    // A big splash carries: its full level reaches farther.
    Placement place{true, position, 4.0f + 12.0f * level, true, 1.0f};

    // The slap: a broad burst, lower and longer for a bigger body.
    StrikeSound slap;
    slap.noise_amplitude = 1.6f * level;
    slap.noise_decay_s = 0.03f + 0.05f * size;
    slap.noise_hz = 1400.0f / (0.6f + 0.6f * size);
    slap.noise_q = 0.5f;
    slap.modes[0] = {180.0f / (0.5f + size), 0.05f + 0.04f * size, 0.5f * level};
    slap.delay = delay;
    slap.seed = seed;
    auto v = std::make_unique<StrikeVoice>(Bus::Effects, slap);
    v->place = place;
    mix.play(std::move(v));

    // The crown's spray falling back: droplet ticks over the next half second.
    auto bubbles = std::make_unique<BubbleVoice>(Bus::Effects, seed + 1u);
    const int drops = int(8 + 30 * level * size);
    for (int i = 0; i < drops; ++i) {
        const float t = rng.unit();
        const float r = 0.0015f + 0.003f * rng.unit();
        bubbles->add(r, 0.5f * level * (1.0f - 0.6f * t), delay + int((0.08f + 0.5f * t * t) * float(kSampleRate)));
    }
    // The entrained air: bubbles of the body's scale ringing at once.
    const int entrained = int(3 + 6 * size);
    for (int i = 0; i < entrained; ++i) {
        const float r = (0.004f + 0.012f * rng.unit()) * (0.6f + 0.5f * size);
        bubbles->add(r, 0.9f * level, delay + int(rng.unit() * 0.04f * float(kSampleRate)));
    }
    bubbles->place = place;
    mix.play(std::move(bubbles));

    if (cause.sinks && cause.mass_kg > 1.0f) {
        // The cavity closes behind a heavy stone: a second, deeper splash, and the jet.
        StrikeSound second;
        const int after = delay + int((0.14f + 0.06f * size) * float(kSampleRate));
        second.delay = after;
        second.noise_amplitude = 0.8f * level;
        second.noise_decay_s = 0.06f;
        second.noise_hz = 700.0f;
        second.modes[0] = {3.0f / (0.03f * size + 0.01f), 0.08f, 0.6f * level};  // the big bubble
        second.seed = seed + 2u;
        auto s = std::make_unique<StrikeVoice>(Bus::Effects, second);
        s->place = place;
        mix.play(std::move(s));
    }
}

}  // namespace audio
