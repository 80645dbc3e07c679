#include "game/audio/LiveSound.h"

#include <iostream>

namespace game {

std::unique_ptr<LiveSound> LiveSound::open(CameraTrack cameras) {
    std::unique_ptr<LiveSound> sound(new LiveSound(std::move(cameras)));
    std::string why;
    sound->output_ = audio::LiveOutput::open(sound->sound_.mixer(), why);
    if (!sound->output_) {
        std::cout << "sound: " << why << ", playing silently" << std::endl;
        return nullptr;
    }
    return sound;
}

LiveSound::~LiveSound() {
    if (output_ && output_->underruns() > 0)
        std::cout << "sound: the device ran dry " << output_->underruns() << " times (the machine was too busy)"
                  << std::endl;
}

void LiveSound::toggle_mute() {
    muted_ = !muted_;
    audio::MixChanges change;
    change.then([muted = muted_](audio::Mixer& m) { m.set_muted(muted); });
    sound_.mixer().submit(std::move(change));
}

void LiveSound::set_volumes(const audio::Volumes& v) {
    audio::MixChanges change;
    change.then([v](audio::Mixer& m) { m.set_volumes(v); });
    sound_.mixer().submit(std::move(change));
}

}  // namespace game
