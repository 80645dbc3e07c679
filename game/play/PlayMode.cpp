#include "game/play/PlayMode.h"

#include <iostream>

#include "game/cli/ExitCode.h"
#include "game/play/GhostRace.h"
#include "game/play/PlayLoop.h"
#include "game/play/ReplayViewer.h"
#include "game/play/WindowScreen.h"
#include "game/replay/ReplayWriter.h"
#include "game/session/ReplayHeaderFor.h"

namespace game {

namespace fs = std::filesystem;

std::vector<std::string> demo_replay_args(const fs::path& replay, uint32_t ticks, const fs::path& out_dir) {
    constexpr uint32_t kEvery = 30;
    std::string frames;
    for (uint32_t t = kEvery; t <= ticks; t += kEvery) {
        if (!frames.empty()) frames += ',';
        frames += std::to_string(t);
    }
    // A replay shorter than the interval still shows its last frame.
    if (frames.empty()) frames = ticks > 0 ? std::to_string(ticks) : "none";
    return {replay.string(), "--headless", "--frames", frames, "--out", out_dir.string()};
}

namespace {

Window::Options window_options(const Settings& settings, std::string title) {
    return Window::Options{.width = settings.window.width,
                           .height = settings.window.height,
                           .title = std::move(title),
                           .vsync = settings.vsync,
                           .x = settings.window.x,
                           .y = settings.window.y,
                           .fullscreen = settings.window.fullscreen};
}

}  // namespace

int play_in_window(GameSession& session, const PlayOptions& options) {
    const Settings& settings = options.player.settings;
    WindowScreen screen(window_options(settings, "Spindrift"));
    std::unique_ptr<LiveSound> sound = LiveSound::open(CameraTrack{});
    std::optional<GhostRace> ghost;
    if (options.ghost) ghost.emplace(*options.ghost, options.ghost_name, session.level.sim, options.threads);
    PlayLoop loop(session, screen,
                  LoopOptions{.quality = settings.quality,
                              .settings = settings,
                              .settings_file = options.player.file.get(),
                              .sound = sound.get(),
                              .ghost = ghost ? &*ghost : nullptr});
    std::optional<ReplayWriter> writer;
    if (options.record) {
        writer.emplace(ReplayWriter::create(*options.record, replay_header_for(session, 480, 270, {})));
        std::cout << "recording to " << writer->partial_path().string() << " (renamed to "
                  << options.record->string() << " at the end)" << std::endl;
    }
    bool recording = writer.has_value();
    TickDriver ticks(*session.world);
    ticks.listen([&](const sim::World& world, sim::TickInput applied) {
        if (!recording) return;
        writer->append(applied, world.hash());
        if (writer->ticks() >= kMaxReplayTicks) {
            // The format's limit: keep playing, stop recording.
            writer->finish();
            recording = false;
            std::cout << "recording stopped at the " << kMaxReplayTicks << "-tick limit" << std::endl;
        }
    });
    if (sound) ticks.listen([&](const sim::World& world, sim::TickInput) { sound->after_tick(world); });
    if (ghost) ticks.listen([&](const sim::World& world, sim::TickInput) { ghost->after_live_tick(world); });
    LoopHooks hooks;  // no next_input: the keyboard drives
    hooks.ticks = &ticks;
    hooks.status = [] { return std::string(); };
    hooks.recording = [&] { return recording; };
    hooks.restart = [&] {
        // The recording is of one course from its start: it ends where the course did.
        if (recording) {
            writer->finish();
            recording = false;
            std::cout << "recording stopped at the restart" << std::endl;
        }
        session.world = std::make_unique<sim::World>(session.level.sim, sim::WorldOptions{options.threads});
        ticks.restart(*session.world);
        if (ghost) ghost->restart();
    };
    loop.run(hooks);
    if (recording) writer->finish();
    if (writer)
        std::cout << "recorded " << writer->ticks() << " ticks of level '" << session.world->level().id << "' to "
                  << writer->path().string() << std::endl;
    return kExitOk;
}

int play_replay_in_window(const Replay& replay, GameSession& session, const PlayerSettings& player,
                          const ViewerOptions& viewer) {
    WindowScreen screen(window_options(player.settings, "Spindrift - replay"));
    const CameraTrack cameras(replay.header.camera_shots, replay.header.tick_rate_hz);
    std::unique_ptr<LiveSound> sound = LiveSound::open(cameras);
    return watch_replay(replay, session, screen,
                        LoopOptions{.quality = player.settings.quality,
                                    .cameras = cameras,
                                    .settings = player.settings,
                                    .settings_file = player.file.get(),
                                    .sound = sound.get()},
                        viewer);
}

}  // namespace game
