#include "game/audio/SessionSound.h"

#include "sim/player/CameraRig.h"

namespace game {

SessionSound::SessionSound(CameraTrack cameras, ListenerFor listener)
    : cameras_(std::move(cameras)), listener_(std::move(listener)), soundscape_(mixer_) {}

void SessionSound::after_tick(const sim::World& world) {
    const sim::CameraView presented = cameras_.view_at(world.tick(), world.get<sim::CameraRig>().view());
    const audio::Listener listener = listener_(world, presented);
    soundscape_.after_tick(world, listener);
}

}  // namespace game
