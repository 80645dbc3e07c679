#pragma once
// A session's sound: the mixer, the soundscape, and the listener, which is the
// presentation camera: the world's camera, or a replay's scripted shot at that tick.
// after_tick is a TickDriver listener.
#include <functional>

#include "audio/Mixer.h"
#include "audio/Soundscape.h"
#include "game/replay/CameraTrack.h"
#include "sim/world/World.h"

namespace game {

class SessionSound {
public:
    using ListenerFor = std::function<audio::Listener(const sim::World&, const sim::CameraView& presented)>;

    explicit SessionSound(CameraTrack cameras = {}, ListenerFor listener = audio::listener_for);
    // Hands the tick's changes to the mixer; never waits for a mixing thread.
    void after_tick(const sim::World& world);

    audio::Mixer& mixer() { return mixer_; }
    const audio::Soundscape& soundscape() const { return soundscape_; }

private:
    CameraTrack cameras_;
    ListenerFor listener_;
    audio::Mixer mixer_;
    audio::Soundscape soundscape_;
};

}  // namespace game
