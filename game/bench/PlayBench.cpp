#include "game/bench/PlayBench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string_view>

#include "game/DataPaths.h"
#include "game/bench/BenchSupport.h"
#include "game/play/FrameTargets.h"
#include "game/play/OffscreenScreen.h"
#include "game/play/Timedemo.h"
#include "game/replay/ReplayReader.h"

namespace game {

namespace fs = std::filesystem;

namespace {

double pass_mean_ms(const TimedemoRun& run, std::string_view name) {
    for (const auto& [pass, ms] : run.pass_ms)
        if (pass == name) return ms;
    return 0.0;
}

// The opaque pass paid for pixels: its mean at scale 0.5 over its mean at scale 1, the
// replay played twice on auto's path with the scale held (1280x720), in milliseconds of
// the same run, so the host's speed drops out.
void bench_opaque_half_scale(BenchReport& report, const Replay& replay, const fs::path& path) {
    double ms[2] = {0.0, 0.0};
    size_t frames[2] = {0, 0};
    const float scales[2] = {0.5f, 1.0f};
    const std::string load_before = load_average();
    for (int i = 0; i < 2; ++i) {
        GameSession session = GameSession::open(replay.header.level_id, 1, replay.header.seed);
        OffscreenScreen screen(1280, 720);
        const TimedemoRun run =
            run_timedemo(replay, path.filename().string(), session, screen, QualityChoice::Auto, scales[i]);
        ms[i] = pass_mean_ms(run, "opaque");
        frames[i] = run.frames.size();
    }
    report.add({"play", path.stem().string() + " auto: opaque pass at scale 0.5 / at scale 1", ms[0] / std::max(ms[1], 1e-6),
                "x", kOpaqueHalfScaleShare, false,
                fmt("%.2f ms over %zu frames / %.2f ms over %zu frames, 1280x720, load %s-%s", ms[0], frames[0], ms[1],
                    frames[1], load_before.c_str(), load_average().c_str())});
}

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
    // The sizes: 1280x720 for every quality; 1920x1080 for auto and high, the
    // same targets in fills of that size.
    struct Size {
        int width, height;
        bool every_quality;
    };
    constexpr Size kSizes[] = {{1280, 720, true}, {1920, 1080, false}};
    for (const fs::path& path : bundled_replays(quick)) {
        const Replay replay = read_replay(path, ReadOptions{});
        const std::string name = path.stem().string();
        for (const Size& size : kSizes)
            for (QualityChoice quality : kQualityChoices) {
                const bool is_auto = quality == QualityChoice::Auto, is_high = quality == QualityChoice::High;
                if (!size.every_quality && !is_auto && !is_high) continue;
                const std::string q(quality_choice_name(quality));
                const std::string label =
                    name + " " + q + (size.width == 1280 ? "" : fmt(" %dx%d", size.width, size.height));
                std::cerr << "bench: play " << label << "\n";
                GameSession session = GameSession::open(replay.header.level_id, 1, replay.header.seed);
                OffscreenScreen screen(size.width, size.height);
                const std::string load_before = load_average();
                const TimedemoRun run = run_timedemo(replay, path.filename().string(), session, screen, quality);
                const TimedemoSummary s = summarise(run);
                const std::string note =
                    fmt("%zu frames, %.1f fps, mean %.1f ms, p95 %.1f ms, game/wall %.2f, fill %.2f ms, load %s-%s%s",
                        s.frames, s.average_fps, s.frame_ms.mean, s.frame_ms.p95, s.wall_s > 0 ? s.game_s / s.wall_s : 0.0,
                        run.fill_ms, load_before.c_str(), load_average().c_str(), run.desync ? ", DESYNC" : "");
                const double fill = std::max(run.fill_ms, 1e-6);
                report.add({"play", label + ": mean frame time in fills", s.frame_ms.mean / fill, "fills",
                            is_auto ? std::optional(kAutoMeanFills) : is_high ? std::optional(kHighMeanFills) : std::nullopt, false, note});
                if (!is_auto) continue;
                report.add({"play", label + ": p95 frame time in fills", s.frame_ms.p95 / fill, "fills", kAutoP95Fills});
                double scale_time = 0.0;
                for (const auto& [scale, secs] : s.seconds_at_scale) scale_time += double(scale) * secs;
                report.add({"play", label + ": time-weighted render scale", s.wall_s > 0 ? scale_time / s.wall_s : 0.0,
                            "x", kAutoMinMeanScale, true});
                // Scales are steps of 0.05 held as floats: 0.35f reads 0.34999... as a double.
                const float lowest = s.seconds_at_scale.empty() ? 0.0f : s.seconds_at_scale.front().first;
                report.add({"play", label + ": lowest render scale", std::round(double(lowest) * 100.0) / 100.0, "x",
                            0.35, true});
                // What is drawn at the output's size: the upscale (or the copy of the
                // resolved frame) and the UI.
                const double output_ms = pass_mean_ms(run, "upscale") + pass_mean_ms(run, "hud");
                report.add({"play", label + ": upscale + HUD at the output's size in fills", output_ms / fill, "fills",
                            kAutoOutputFills});
            }
        std::cerr << "bench: play " << name << " auto, the opaque pass at scale 0.5 and 1\n";
        bench_opaque_half_scale(report, replay, path);
    }
}

}  // namespace game
