#pragma once
// `spindrift timedemo`: a replay played through the same PlayLoop as `play`, ticks
// advanced by real time, every frame drawn as the player sees it (HUD included), timed.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "game/play/PlayLoop.h"
#include "game/play/QualityChoice.h"
#include "game/play/Screen.h"
#include "game/replay/ReplayReader.h"
#include "game/session/GameSession.h"

namespace game {

// What one run measured, frame by frame.
struct TimedemoRun {
    std::string replay;  // the replay's file name
    std::string renderer;  // GL_RENDERER
    int width = 0, height = 0;
    QualityChoice quality = QualityChoice::Auto;
    std::vector<FrameRecord> frames;  // the first (warm-up) frame left out
    std::vector<std::pair<std::string, double>> pass_ms;  // per pass, mean over the frames (and "hud": the UI)
    // Draw calls and triangles per frame, mean over the frames: per pass that drew any
    // (effects::gl::DrawCount), and the frame's total.
    struct Draws {
        std::string pass;
        double draws = 0.0, triangles = 0.0;
    };
    std::vector<Draws> pass_draws;
    Draws frame_draws{"frame"};
    double fill_ms = 0.0;  // TrivialFill at the output's size, in the same run
    uint64_t ticks = 0, replay_ticks = 0;
    size_t hashes_checked = 0;
    std::optional<std::string> desync;  // the first divergence, if the world left the replay
};

// Plays `replay` (the session opened for it) on `screen` until its inputs end; at
// `scale` throughout when given (auto: instead of its controller).
TimedemoRun run_timedemo(const Replay& replay, const std::string& replay_name, GameSession& session,
                         Screen& screen, QualityChoice quality, std::optional<float> scale = std::nullopt);

// The run as numbers.
struct TimedemoSummary {
    struct Percentiles {
        double mean = 0.0, p50 = 0.0, p95 = 0.0, p99 = 0.0, worst = 0.0;
    };
    size_t frames = 0;
    double wall_s = 0.0;   // the frames' times added up
    double game_s = 0.0;   // ticks run over them at 60 Hz
    double average_fps = 0.0;
    Percentiles frame_ms;
    std::vector<float> scale_each_second;  // render scale at the end of each whole second
    std::vector<std::pair<float, double>> seconds_at_scale;  // ascending scale
};
TimedemoSummary summarise(const TimedemoRun& run);

void print_timedemo(const TimedemoRun& run, const TimedemoSummary& summary);
// Written through a temporary file and a rename. Throws CaptureError when it cannot be.
void write_timedemo_json(const std::filesystem::path& path, const TimedemoRun& run, const TimedemoSummary& summary);

}  // namespace game
