#pragma once
// One sound the mixer plays: a model that writes mono samples, where it is in the
// world and which bus it is heard on. Persistent voices (the engine, the rain) are
// updated by the Soundscape once a tick; one-shots (a splash, a cue) end themselves.
#include <glm/vec3.hpp>

namespace audio {

// The four volumes of the debug panel are master and these three; cues go with the effects.
enum class Bus { Engine, Effects, Ambience };
inline constexpr int kBusCount = 3;

struct Placement {
    bool positioned = false;       // else heard in the middle at `gain` (cues, beds)
    glm::vec3 position{0.0f};
    float reference_m = 4.0f;      // full level within this distance, then 1/distance
    bool outside = true;           // muffled when the listener sits in the cabin
    float doppler = 1.0f;          // how much the Doppler shift applies (0 for beds)
};

class Voice {
public:
    explicit Voice(Bus bus) : bus_(bus) {}
    virtual ~Voice() = default;
    // Adds `frames` samples to `out` with the pitch scaled by `pitch` (the Doppler factor).
    // Returns false once the voice has finished and can be dropped.
    virtual bool render(float* out, int frames, float pitch) = 0;
    // The level the voice is now set to, 0 when silent (so the mixer can skip it).
    virtual bool audible() const { return true; }

    Bus bus() const { return bus_; }
    Placement place;

private:
    Bus bus_;
};

}  // namespace audio
