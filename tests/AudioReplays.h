#pragma once
// The audio tests' replays: a bundled replay and a fresh session for it, and a render
// that also records, tick by tick, what the sim says happened (the events whose
// onsets must be heard) and what the sound models were told.
#include <filesystem>
#include <string>
#include <vector>

#include "game/DataPaths.h"
#include "game/audio/ReplaySound.h"
#include "game/replay/ReplayReader.h"
#include "game/session/GameSession.h"
#include "game/session/TickDriver.h"
#include "sim/rain/RainSim.h"
#include "sim/weather/Weather.h"

namespace audio_test {

struct TickLog {
    uint64_t tick = 0;
    float rain_rate = 0.0f;
    float engine_rpm = 0.0f;
    bool event = false;  // a splash, shot fired, shot impact or wiper reversal this tick
    int gear = 1;
};

struct Render {
    std::vector<float> samples;  // interleaved stereo
    std::vector<TickLog> ticks;  // one per tick rendered, in order
};

inline game::Replay bundled(const std::string& name) {
    return game::read_replay(game::data_dir() / "replays" / (name + ".replay"), game::ReadOptions{});
}

// Renders `ticks` ticks (0: all) of the bundled replay `name`.
inline Render render(const std::string& name, uint32_t ticks, audio::Volumes volumes = {},
                     game::SessionSound::ListenerFor listener = audio::listener_for) {
    const game::Replay replay = bundled(name);
    game::GameSession session = game::GameSession::open(replay.header.level_id, 1, replay.header.seed);
    game::OfflineSound offline(game::CameraTrack(replay.header.camera_shots, replay.header.tick_rate_hz), listener);
    offline.sound().mixer().set_volumes(volumes);
    Render r;
    float turning = 0.0f;
    game::TickDriver driver(*session.world);
    driver.listen([&](const sim::World& world, sim::TickInput) {
        const std::vector<float>& tick = offline.after_tick(world);
        r.samples.insert(r.samples.end(), tick.begin(), tick.end());
        TickLog log;
        log.tick = world.tick();
        const sim::TickReport& report = world.report();
        log.event = !report.water_entries.empty() || !report.shots_fired.empty() || !report.shot_impacts.empty();
        if (const sim::RainSim* rain = world.find<sim::RainSim>()) {
            const float now = rain->blades()[0].turning();
            if (turning != 0.0f && now != turning) log.event = true;
            turning = now;
        }
        if (const sim::Weather* w = world.find<sim::Weather>()) log.rain_rate = w->rain_rate();
        log.engine_rpm = offline.sound().soundscape().state().engine_rpm;
        log.gear = offline.sound().soundscape().state().gear;
        r.ticks.push_back(log);
    });
    const size_t n = ticks ? std::min<size_t>(ticks, replay.inputs.size()) : replay.inputs.size();
    for (size_t i = 0; i < n; ++i) driver.step(replay.inputs[i]);
    return r;
}

}  // namespace audio_test
