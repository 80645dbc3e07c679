#pragma once
// Sound in a window (play, replay): the session's sound through the default audio
// device. Without one it says so in one line and the game runs silently.
#include <memory>

#include "audio/LiveOutput.h"
#include "game/audio/SessionSound.h"

namespace game {

class LiveSound {
public:
    // Prints one line and returns nullptr when there is no audio device.
    static std::unique_ptr<LiveSound> open(CameraTrack cameras);
    ~LiveSound();  // says how often the device ran dry, if it did

    void after_tick(const sim::World& world) { sound_.after_tick(world); }
    void set_paused(bool paused) { output_->set_paused(paused); }
    void toggle_mute();
    bool muted() const { return muted_; }
    void set_volumes(const audio::Volumes& v);
    // Blocks the device ran dry before the mixing thread refilled it, so far.
    int underruns() const { return output_->underruns(); }

private:
    explicit LiveSound(CameraTrack cameras) : sound_(std::move(cameras)) {}
    SessionSound sound_;
    std::unique_ptr<audio::LiveOutput> output_;  // after the mixer it reads: stopped first
    bool muted_ = false;  // as last told to the mixer
};

}  // namespace game
