#include "game/audio/LiveSound.h"

#include <iostream>
#include <mutex>

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
    std::lock_guard lock(sound_.mixer().mutex());
    sound_.mixer().set_muted(!sound_.mixer().muted());
}

bool LiveSound::muted() {
    std::lock_guard lock(sound_.mixer().mutex());
    return sound_.mixer().muted();
}

void LiveSound::set_volumes(const audio::Volumes& v) {
    std::lock_guard lock(sound_.mixer().mutex());
    sound_.mixer().set_volumes(v);
}

}  // namespace game
