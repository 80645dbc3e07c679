#pragma once
// Play in a window: the keyboard (or a replay) drives the world at 60 ticks per second
// of real time, the renderer draws into the window, Dear ImGui draws the HUD and the
// debug panel on top.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "game/replay/ReplayReader.h"
#include "game/session/GameSession.h"

namespace game {

// Turns real time into a whole number of fixed ticks per frame. Counts in whole
// nanoseconds times the tick rate, so no rounding drift builds up over a long session.
class FixedStepClock {
public:
    // At most `max_ticks_per_frame` ticks per frame: a slow frame makes the world run
    // slower than real time instead of falling ever further behind.
    explicit FixedStepClock(int tick_rate_hz, int max_ticks_per_frame = 5);

    // Adds the real time since the last frame; returns how many ticks to run now.
    int advance(std::chrono::nanoseconds elapsed);
    // Forgets accumulated time, so that a pause is not made up for afterwards.
    void reset() { pending_ = 0; }
    // Time accumulated towards the next tick.
    std::chrono::nanoseconds pending() const { return std::chrono::nanoseconds(pending_ / rate_hz_); }

private:
    static constexpr int64_t kNsPerSecond = 1'000'000'000;
    int64_t rate_hz_;
    int max_ticks_;
    int64_t pending_ = 0;  // nanoseconds * rate_hz_: a tick is kNsPerSecond of these
};

struct PlayOptions {
    std::optional<std::filesystem::path> record;  // record the session to this replay
};

// The keyboard drives `session` until the window is closed or Esc; returns an ExitCode.
// Throws std::runtime_error when no window can be opened, ReplayError when the recording
// cannot be written.
int play_in_window(GameSession& session, const PlayOptions& options);

// Plays the replay's inputs at 60 ticks/s with the HUD shown and checks its stored
// hashes on the way; P pauses, Esc quits. At the end the last frame stays up until the
// window is closed. Returns kExitCheckFailed if the world diverged, else kExitOk.
int play_replay_in_window(const Replay& replay, GameSession& session);

// Where F12 writes a screenshot taken at `when` (local time, to the millisecond):
// screenshots/spindrift_YYYYMMDD-HHMMSS-mmm.png.
std::filesystem::path screenshot_path(std::chrono::system_clock::time_point when);

// The `replay` command line that renders every 30th tick of a replay `ticks` long
// headless into `out_dir`: what `play` does without a display.
std::vector<std::string> demo_replay_args(const std::filesystem::path& replay, uint32_t ticks,
                                          const std::filesystem::path& out_dir);

}  // namespace game
