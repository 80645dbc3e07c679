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

// What the sim says happened in a tick that must be heard at its onset.
enum Event : unsigned {
    kSplash = 1, kShotFired = 2, kShotImpact = 4, kWiperReversal = 8,
    kKnock = 16,  // a contact whose speed change is at least kKnockDv after kKnockQuiet ticks without one
    kCue = 32,    // a gate passed, a lap finished, a target hit
};
inline constexpr float kKnockDv = 0.4f;  // m/s: the soundscape's least audible knock
inline constexpr uint64_t kKnockQuiet = 8;

inline std::string event_names(unsigned events) {
    std::string s;
    const char* names[] = {"splash", "shot", "impact", "reversal", "knock", "cue"};
    for (unsigned i = 0; i < 6; ++i)
        if (events & (1u << i)) s += std::string(s.empty() ? "" : "+") + names[i];
    return s;
}

struct TickLog {
    uint64_t tick = 0;
    float rain_rate = 0.0f;
    float engine_rpm = 0.0f;
    unsigned events = 0;  // Event bits
    bool event = false;   // any of them
    int gear = 1;
    audio::SoundState sound;  // what the sound models were told
};

struct Render {
    std::vector<float> samples;  // interleaved stereo
    std::vector<TickLog> ticks;  // one per tick rendered, in order
};

inline game::Replay bundled(const std::string& name) {
    return game::read_replay(game::data_dir() / "replays" / (name + ".replay"), game::ReadOptions{});
}

// Renders `ticks` ticks (0: all) of `replay`.
inline Render render(const game::Replay& replay, uint32_t ticks, audio::Volumes volumes = {},
                     game::SessionSound::ListenerFor listener = audio::listener_for) {
    game::GameSession session = game::GameSession::open(replay.header.level_id, 1, replay.header.seed);
    game::OfflineSound offline(game::CameraTrack(replay.header.camera_shots, replay.header.tick_rate_hz), listener);
    offline.sound().mixer().set_volumes(volumes);
    Render r;
    float turning = 0.0f;
    uint64_t last_contact = 0;
    bool contact_before = false;
    game::TickDriver driver(*session.world);
    driver.listen([&](const sim::World& world, sim::TickInput) {
        const std::vector<float>& tick = offline.after_tick(world);
        r.samples.insert(r.samples.end(), tick.begin(), tick.end());
        TickLog log;
        log.tick = world.tick();
        const sim::TickReport& report = world.report();
        if (!report.water_entries.empty()) log.events |= kSplash;
        if (!report.shots_fired.empty()) log.events |= kShotFired;
        if (!report.shot_impacts.empty()) log.events |= kShotImpact;
        if (const sim::RainSim* rain = world.find<sim::RainSim>()) {
            const float now = rain->blades()[0].turning();
            if (turning != 0.0f && now != turning) log.events |= kWiperReversal;
            turning = now;
        }
        for (const sim::ContactReport& c : report.contacts) {
            const float mass = c.body == sim::ContactBody::Car ? 1300.0f : 1500.0f;  // as the soundscape weighs them
            if (c.impulse_ns / mass >= kKnockDv && (!contact_before || log.tick >= last_contact + kKnockQuiet))
                log.events |= kKnock;
        }
        if (!report.contacts.empty()) {
            last_contact = log.tick;
            contact_before = true;
        }
        if (!report.gates.empty() || !report.targets_hit.empty()) log.events |= kCue;
        log.event = log.events != 0;
        if (const sim::Weather* w = world.find<sim::Weather>()) log.rain_rate = w->rain_rate();
        log.engine_rpm = offline.sound().soundscape().state().engine_rpm;
        log.gear = offline.sound().soundscape().state().gear;
        log.sound = offline.sound().soundscape().state();
        r.ticks.push_back(log);
    });
    const size_t n = ticks ? std::min<size_t>(ticks, replay.inputs.size()) : replay.inputs.size();
    for (size_t i = 0; i < n; ++i) driver.step(replay.inputs[i]);
    return r;
}

// Renders `ticks` ticks (0: all) of the bundled replay `name`.
inline Render render(const std::string& name, uint32_t ticks, audio::Volumes volumes = {},
                     game::SessionSound::ListenerFor listener = audio::listener_for) {
    return render(bundled(name), ticks, volumes, std::move(listener));
}

}  // namespace audio_test
