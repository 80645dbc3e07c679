#pragma once
// A body entering the water, from its mass and speed (sim::WaterEntry): the impact's
// slap, the crown's spray falling back as droplet ticks, the entrained air ringing as
// bubbles (van den Doel 2005, see Bubbles.h), and for a heavy body that sinks the
// cavity's collapse a moment later: a second, lower splash with the jet. After the
// stages of a solid's water entry in A. M. Worthington, "A Study of Splashes" (1908)
// (the crown, the cavity, the jet).
#include <memory>

#include "audio/MixChanges.h"

namespace audio {

struct SplashCause {
    float mass_kg = 1.0f;
    float speed_mps = 5.0f;
    float radius_m = 0.2f;
    bool sinks = false;
};

// Starts the splash's voices at `position` (as changes to the mix); `seed` picks its randomness.
void play_splash(MixChanges& mix, const SplashCause& cause, glm::vec3 position, uint32_t seed, int delay);

}  // namespace audio
