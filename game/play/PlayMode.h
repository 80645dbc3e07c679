#pragma once
// Play in a window: the keyboard (or a replay) drives the world through the PlayLoop.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "game/play/QualityChoice.h"
#include "game/replay/ReplayReader.h"
#include "game/session/GameSession.h"
#include "game/settings/SettingsFile.h"

namespace game {

struct PlayOptions {
    std::optional<std::filesystem::path> record;  // record the session to this replay
    PlayerSettings player;  // the window, quality, keys, ... and where changes are kept
    int threads = 1;        // the sim's, for a restarted world too
    // A replay of the session's level to race (play --ghost), and its name on the HUD.
    std::optional<Replay> ghost;
    std::string ghost_name;
};

// The keyboard drives `session` until the window is closed or the menu's Quit; returns an ExitCode.
// Throws std::runtime_error when no window can be opened, ReplayError when the recording
// cannot be written.
int play_in_window(GameSession& session, const PlayOptions& options);

// The replay viewer's (ReplayViewer's) options.
struct ViewerOptions {
    // A take over records the old inputs up to its tick and the new ones after to this file.
    std::optional<std::filesystem::path> record;
    int threads = 1;  // the take over's re-simulation's
};

// The replay viewer (game/play/ReplayViewer.h): plays the replay's inputs in real time with
// a timeline, pause, single ticks, speeds, markers, seeks, cameras and a take over (keys:
// docs/REPLAYS.md), checking its stored hashes; Esc opens the menu. Returns kExitCheckFailed
// if the world diverged, kExitIo if a take over could not be recorded, else kExitOk.
int play_replay_in_window(const Replay& replay, GameSession& session, const PlayerSettings& player,
                          const ViewerOptions& viewer);

// The `replay` command line that renders every 30th tick of a replay `ticks` long
// headless into `out_dir`: what `play` does without a display.
std::vector<std::string> demo_replay_args(const std::filesystem::path& replay, uint32_t ticks,
                                          const std::filesystem::path& out_dir);

}  // namespace game
