#include "game/audio/ReplaySound.h"

#include <stdexcept>

#include "game/DataPaths.h"

namespace game {

OfflineSound::OfflineSound(CameraTrack cameras, SessionSound::ListenerFor listener)
    : sound_(std::move(cameras), std::move(listener)), tick_(size_t(2 * kFramesPerTick)) {
    std::string why;
    if (!audio::pin_openal_settings(data_dir() / "audio" / "alsoft-offline.conf", why) ||
        !(render_ = audio::LoopbackRender::open(sound_.mixer(), why)))
        throw std::runtime_error("cannot render sound: " + why);
}

const std::vector<float>& OfflineSound::after_tick(const sim::World& world) {
    sound_.after_tick(world);
    render_->render(tick_.data(), kFramesPerTick);
    return tick_;
}

std::vector<float> render_replay_sound(const Replay& replay, GameSession& session, const SoundRenderOptions& options) {
    OfflineSound offline(CameraTrack(replay.header.camera_shots, replay.header.tick_rate_hz), options.listener);
    offline.sound().mixer().set_volumes(options.volumes);
    const size_t ticks = options.ticks ? std::min<size_t>(options.ticks, replay.inputs.size()) : replay.inputs.size();
    std::vector<float> samples;
    samples.reserve(ticks * 2 * kFramesPerTick);
    TickDriver driver(*session.world);
    driver.listen([&](const sim::World& world, sim::TickInput) {
        const std::vector<float>& tick = offline.after_tick(world);
        samples.insert(samples.end(), tick.begin(), tick.end());
    });
    for (size_t i = 0; i < ticks; ++i) driver.step(replay.inputs[i]);
    return samples;
}

}  // namespace game
