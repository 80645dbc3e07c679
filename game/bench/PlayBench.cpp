#include "game/bench/PlayBench.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "game/DataPaths.h"
#include "game/bench/BenchSupport.h"
#include "game/play/OffscreenScreen.h"
#include "game/play/Timedemo.h"
#include "game/replay/ReplayReader.h"

namespace game {

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> bundled_replays(bool quick) {
    const fs::path dir = data_dir() / "replays";
    if (quick) return {dir / "harbour_drive.replay"};
    std::vector<fs::path> out;
    for (const fs::directory_entry& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".replay") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

void bench_play(BenchReport& report, bool quick) {
    constexpr int kWidth = 1280, kHeight = 720;
    for (const fs::path& path : bundled_replays(quick)) {
        const Replay replay = read_replay(path, ReadOptions{});
        const std::string name = path.stem().string();
        for (QualityChoice quality : kQualityChoices) {
            const std::string q(quality_choice_name(quality));
            std::cerr << "bench: play " << name << " " << q << "\n";
            GameSession session = GameSession::open(replay.header.level_id, 1, replay.header.seed);
            OffscreenScreen screen(kWidth, kHeight);
            const TimedemoRun run = run_timedemo(replay, path.filename().string(), session, screen, quality);
            const TimedemoSummary s = summarise(run);
            const std::string label = name + " " + q;
            const std::string note = fmt("%zu frames, p50 %.1f ms, worst %.1f ms, game/wall %.2f, fill %.2f ms%s",
                                         s.frames, s.frame_ms.p50, s.frame_ms.worst,
                                         s.wall_s > 0 ? s.game_s / s.wall_s : 0.0, run.fill_ms,
                                         run.desync ? ", DESYNC" : "");
            const bool is_auto = quality == QualityChoice::Auto;
            const double fill = std::max(run.fill_ms, 1e-6);
            report.add({"play", label + ": average fps", s.average_fps, "fps",
                        is_auto ? std::optional(30.0) : std::nullopt, true, note});
            report.add({"play", label + ": p95 frame time", s.frame_ms.p95, "ms",
                        is_auto ? std::optional(50.0) : std::nullopt});
            report.add({"play", label + ": p95 frame time in fills", s.frame_ms.p95 / fill, "fills",
                        is_auto ? std::optional(40.0) : std::nullopt});
            report.add({"play", label + ": mean frame time", s.frame_ms.mean, "ms",
                        quality == QualityChoice::High ? std::optional(85.0) : std::nullopt});
            if (is_auto) {
                double scale_time = 0.0;
                for (const auto& [scale, secs] : s.seconds_at_scale) scale_time += double(scale) * secs;
                report.add({"play", label + ": time-weighted render scale",
                            s.wall_s > 0 ? scale_time / s.wall_s : 0.0, "x"});
            }
        }
    }
}

}  // namespace game
