#include "game/play/Timedemo.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <span>

#include <nlohmann/json.hpp>

#include "effects/gl/Gl.h"
#include "game/bench/BenchSupport.h"
#include "game/bench/TrivialFill.h"
#include "game/capture/ImageFiles.h"
#include "game/replay/ReplayCheck.h"

namespace game {

TimedemoRun run_timedemo(const Replay& replay, const std::string& replay_name, GameSession& session,
                         Screen& screen, QualityChoice quality, std::optional<float> scale) {
    TimedemoRun run;
    run.replay = replay_name;
    run.quality = quality;
    run.replay_ticks = replay.inputs.size();
    const Screen::Size size = screen.size();
    run.width = size.width;
    run.height = size.height;
    if (const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER))) run.renderer = text;
    // Half the samples before the run and half after it, and the median of them all: the
    // machine's state can change while the replay plays.
    constexpr int kFillsEachSide = 11;
    std::vector<double> fills = trivial_fill_samples(size.width, size.height, kFillsEachSide);

    PlayLoop loop(session, screen,
                  LoopOptions{.quality = quality,
                              .render_scale = scale,
                              .pause_when_unfocused = false,
                              .end_with_input = true,
                              .cameras = CameraTrack(replay.header.camera_shots, replay.header.tick_rate_hz)});
    ReplayChecker checker(replay);
    size_t next = 0;
    std::map<std::string, size_t> pass_index, draws_index;
    std::vector<double> pass_sums;
    TickDriver ticks(*session.world);
    ticks.listen([&](const sim::World& world, sim::TickInput) {
        ++run.ticks;
        if (run.desync) return;
        if (auto divergence = checker.after_step(world)) run.desync = divergence->message;
    });
    LoopHooks hooks;
    hooks.ticks = &ticks;
    hooks.next_input = [&]() -> std::optional<sim::TickInput> {
        if (next >= replay.inputs.size()) return std::nullopt;
        return replay.inputs[next++];
    };
    hooks.status = [&] {
        return "timedemo " + std::to_string(next) + "/" + std::to_string(replay.inputs.size()) +
               (run.desync ? "  DESYNC" : "");
    };
    hooks.recording = [] { return false; };
    hooks.after_frame = [&](const FrameRecord& frame) {
        run.frames.push_back(frame);
        // Each pass's latest exact measurement, every frame: a mean over the run.
        for (const effects::gl::PassTime& p : loop.renderer().pass_times()) {
            auto [it, added] = pass_index.try_emplace(p.name, run.pass_ms.size());
            if (added) run.pass_ms.emplace_back(p.name, 0.0);
            run.pass_ms[it->second].second += p.ms;
        }
        // The UI drawn at the output's size after the passes, timed by the loop.
        auto [hud, added] = pass_index.try_emplace("hud", run.pass_ms.size());
        if (added) run.pass_ms.emplace_back("hud", 0.0);
        run.pass_ms[hud->second].second += loop.ui_ms();
        for (const effects::Renderer::PassDraws& d : loop.renderer().pass_draws()) {
            auto [it, added_draws] = draws_index.try_emplace(d.name, run.pass_draws.size());
            if (added_draws) run.pass_draws.push_back({d.name});
            run.pass_draws[it->second].draws += double(d.count.draws);
            run.pass_draws[it->second].triangles += double(d.count.triangles);
            run.frame_draws.draws += double(d.count.draws);
            run.frame_draws.triangles += double(d.count.triangles);
        }
    };
    loop.run(hooks);
    const std::vector<double> after = trivial_fill_samples(size.width, size.height, kFillsEachSide);
    fills.insert(fills.end(), after.begin(), after.end());
    run.fill_ms = median_ms(fills);
    const double frames = double(std::max<size_t>(run.frames.size(), 1));
    for (auto& [name, ms] : run.pass_ms) ms /= frames;
    auto mean = [frames](TimedemoRun::Draws& d) {
        d.draws /= frames;
        d.triangles /= frames;
    };
    mean(run.frame_draws);
    for (TimedemoRun::Draws& d : run.pass_draws) mean(d);
    run.hashes_checked = checker.hashes_checked();
    return run;
}

namespace {

double nearest_rank(const std::vector<double>& sorted, double q) {
    if (sorted.empty()) return 0.0;
    const size_t rank = size_t(std::ceil(q * double(sorted.size())));
    return sorted[std::clamp<size_t>(rank, 1, sorted.size()) - 1];
}

}  // namespace

TimedemoSummary summarise(const TimedemoRun& run) {
    TimedemoSummary s;
    s.frames = run.frames.size();
    std::vector<double> ms;
    std::map<float, double> at_scale;
    uint64_t ticks = 0;
    double t_ms = 0.0;
    for (const FrameRecord& f : run.frames) {
        ms.push_back(f.frame_ms);
        ticks += uint64_t(f.ticks);
        at_scale[f.render_scale] += f.frame_ms * 1e-3;
        t_ms += f.frame_ms;
        while (t_ms >= 1000.0 * double(s.scale_each_second.size() + 1)) s.scale_each_second.push_back(f.render_scale);
    }
    s.wall_s = t_ms * 1e-3;
    s.game_s = double(ticks) / double(sim::kTickRateHz);
    s.average_fps = s.wall_s > 0.0 ? double(s.frames) / s.wall_s : 0.0;
    std::sort(ms.begin(), ms.end());
    s.frame_ms = {ms.empty() ? 0.0 : t_ms / double(ms.size()), nearest_rank(ms, 0.50), nearest_rank(ms, 0.95),
                  nearest_rank(ms, 0.99), ms.empty() ? 0.0 : ms.back()};
    s.seconds_at_scale.assign(at_scale.begin(), at_scale.end());
    return s;
}

void print_timedemo(const TimedemoRun& run, const TimedemoSummary& s) {
    const double fill = run.fill_ms > 0.0 ? run.fill_ms : 1.0;
    std::printf("timedemo %s at %dx%d, quality %s (%s)\n", run.replay.c_str(), run.width, run.height,
                std::string(quality_choice_name(run.quality)).c_str(), run.renderer.c_str());
    std::printf("  %zu frames in %.2f s: %.1f fps; game time / wall time %.3f (%llu of %llu ticks)\n", s.frames,
                s.wall_s, s.average_fps, s.wall_s > 0 ? s.game_s / s.wall_s : 0.0,
                static_cast<unsigned long long>(run.ticks), static_cast<unsigned long long>(run.replay_ticks));
    std::printf("  trivial fill %.3f ms; times below also in fills\n", run.fill_ms);
    std::printf("  %-22s %10s %10s\n", "frame time", "ms", "fills");
    const std::pair<const char*, double> rows[] = {{"mean", s.frame_ms.mean},   {"p50", s.frame_ms.p50},
                                                   {"p95", s.frame_ms.p95},     {"p99", s.frame_ms.p99},
                                                   {"worst", s.frame_ms.worst}};
    for (const auto& [name, ms] : rows) std::printf("  %-22s %10.2f %10.1f\n", name, ms, ms / fill);
    std::printf("  %-22s %10s %10s\n", "pass (mean)", "ms", "fills");
    for (const auto& [name, ms] : run.pass_ms) std::printf("  %-22s %10.2f %10.1f\n", name.c_str(), ms, ms / fill);
    std::printf("  %-22s %10s %10s\n", "drawn (mean a frame)", "draws", "triangles");
    for (const TimedemoRun::Draws& d : run.pass_draws)
        std::printf("  %-22s %10.0f %10.0f\n", d.pass.c_str(), d.draws, d.triangles);
    std::printf("  %-22s %10.0f %10.0f\n", "frame", run.frame_draws.draws, run.frame_draws.triangles);
    std::string timeline;
    for (float scale : s.scale_each_second) timeline += fmt(" %.2f", double(scale));
    std::printf("  render scale each second:%s\n", timeline.empty() ? " -" : timeline.c_str());
    for (const auto& [scale, secs] : s.seconds_at_scale)
        std::printf("  at scale %.2f (%dx%d): %.2f s\n", double(scale), int(std::lround(run.width * scale)),
                    int(std::lround(run.height * scale)), secs);
    std::printf("  %zu hash checks%s\n", run.hashes_checked, run.desync ? (", DESYNC at " + *run.desync).c_str() : ", all matched");
}

void write_timedemo_json(const std::filesystem::path& path, const TimedemoRun& run, const TimedemoSummary& s) {
    const double fill = run.fill_ms > 0.0 ? run.fill_ms : 1.0;
    auto percentiles = [](const TimedemoSummary::Percentiles& p, double unit) {
        return nlohmann::json{{"mean", p.mean / unit}, {"p50", p.p50 / unit},     {"p95", p.p95 / unit},
                              {"p99", p.p99 / unit},   {"worst", p.worst / unit}};
    };
    nlohmann::json j{{"replay", run.replay},
                     {"renderer", run.renderer},
                     {"width", run.width},
                     {"height", run.height},
                     {"quality", quality_choice_name(run.quality)},
                     {"frames", s.frames},
                     {"wall_s", s.wall_s},
                     {"game_s", s.game_s},
                     {"game_over_wall", s.wall_s > 0 ? s.game_s / s.wall_s : 0.0},
                     {"average_fps", s.average_fps},
                     {"ticks", run.ticks},
                     {"replay_ticks", run.replay_ticks},
                     {"fill_ms", run.fill_ms},
                     {"frame_ms", percentiles(s.frame_ms, 1.0)},
                     {"frame_fills", percentiles(s.frame_ms, fill)},
                     {"hashes_checked", run.hashes_checked},
                     {"desync", run.desync ? nlohmann::json(*run.desync) : nlohmann::json(nullptr)}};
    j["passes"] = nlohmann::json::array();
    for (const auto& [name, ms] : run.pass_ms) j["passes"].push_back({{"name", name}, {"ms", ms}, {"fills", ms / fill}});
    auto draws = [](const TimedemoRun::Draws& d) {
        return nlohmann::json{{"name", d.pass}, {"draws", d.draws}, {"triangles", d.triangles}};
    };
    j["draws"] = nlohmann::json::array();
    for (const TimedemoRun::Draws& d : run.pass_draws) j["draws"].push_back(draws(d));
    j["frame_draws"] = draws(run.frame_draws);
    j["scale_each_second"] = s.scale_each_second;
    j["seconds_at_scale"] = nlohmann::json::array();
    for (const auto& [scale, secs] : s.seconds_at_scale)
        j["seconds_at_scale"].push_back({{"scale", scale}, {"seconds", secs}});
    const std::string text = j.dump(2) + "\n";
    write_file_atomically(path, std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));
}

}  // namespace game
