// spindrift bench [--json FILE] [--quick] [--only GROUP,...]
#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "effects/Renderer.h"
#include "game/bench/BenchReport.h"
#include "game/bench/BenchSupport.h"
#include "game/bench/EnergyBench.h"
#include "game/bench/AudioBench.h"
#include "game/bench/RainBench.h"
#include "game/bench/FluidBench.h"
#include "game/bench/DustBench.h"
#include "game/bench/PlayBench.h"
#include "game/bench/ReplayBench.h"
#include "game/bench/SubsystemTimer.h"
#if SPINDRIFT_VIDEO
#include "game/bench/VideoBench.h"
#endif
#include "game/bench/WaterBench.h"
#include "game/capture/FrameCapture.h"
#include "game/cli/Args.h"
#include "game/cli/BenchGroups.h"
#include "game/cli/Commands.h"
#include "game/cli/ExitCode.h"
#include "game/platform/HeadlessContext.h"
#include "game/session/GameSession.h"

namespace game {

namespace {

using Clock = std::chrono::steady_clock;

// A busy, repeatable session: driving with turns, throws and shots.
sim::TickInput bench_input(uint32_t tick) {
    sim::TickInput in;
    in.set(sim::Control::Throttle, (tick / 240) % 4 != 3);
    in.set(sim::Control::Brake, (tick / 240) % 4 == 3);
    in.set((tick / 150) % 2 ? sim::Control::SteerLeft : sim::Control::SteerRight, (tick % 150) < 60);
    in.set(sim::Control::ThrowHeavy, tick % 90 == 10);
    in.set(sim::Control::ThrowLight, tick % 90 == 55);
    in.set(sim::Control::Fire, tick % 150 == 20);
    return in;
}

double peak_resident_mib() {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmHWM:") {
            double kib = 0;
            status >> kib;
            return kib / 1024.0;
        }
        std::getline(status, key);
    }
    return 0.0;
}

void bench_sim(BenchReport& report, uint32_t ticks) {
    GameSession s = GameSession::open("harbour", 1);
    SubsystemTimer timer(s.world->subsystems().size());
    auto start = Clock::now();
    for (uint32_t t = 0; t < ticks; ++t) s.world->step(bench_input(t), &timer);
    double total = seconds_since(start);
    std::vector<std::string> names = s.world->subsystem_names();
    for (size_t i = 0; i < names.size(); ++i)
        report.add({"sim", "step " + names[i] + " per tick", timer.total_seconds()[i] * 1e3 / ticks, "ms"});
    report.add({"sim", "whole sim per tick (1 thread)", total * 1e3 / ticks, "ms", 8.0, false,
                std::to_string(ticks) + " ticks of the harbour level"});
}

void bench_replay_check(BenchReport& report, uint32_t ticks) {
    // What `replay --check --frames none` does per tick: step, then hash.
    GameSession s = GameSession::open("harbour", 1);
    auto start = Clock::now();
    uint64_t sink = 0;
    for (uint32_t t = 0; t < ticks; ++t) {
        s.world->step(bench_input(t));
        sink ^= s.world->hash().world;
    }
    double secs = seconds_since(start);
    report.add({"replay", "check without rendering", (ticks / 60.0) / secs, "x realtime", 50.0, true,
                "hash " + std::to_string(sink & 0xffff)});
}

void bench_render(BenchReport& report, int width, int height, int frames) {
    GameSession s = GameSession::open("harbour", 1);
    effects::Renderer renderer(s.level.scene, *s.world, {.timing = effects::gl::TimingMode::Profile});
    FrameCapture capture(width, height);
    std::map<std::string, double> pass_ms;
    std::vector<std::string> order;
    // Draw calls and triangles a frame, per pass: the same views every run, so the same
    // counts whatever the machine's load (the timedemo's depend on which frames it drew).
    std::map<std::string, effects::gl::DrawCount> drawn;
    std::vector<std::string> drawn_order;
    double frame_s = 0.0;
    // Warm up once (shader compile, first-use allocations), then time frames spread
    // over a drive so the view changes.
    renderer.render(*s.world, capture.output());
    glFinish();
    uint32_t tick = 0;
    for (int f = 0; f < frames; ++f) {
        for (int k = 0; k < 40; ++k) s.world->step(bench_input(tick++));
        auto start = Clock::now();
        renderer.render(*s.world, capture.output());
        glFinish();
        frame_s += seconds_since(start);
        for (const auto& p : renderer.pass_times()) {
            if (!pass_ms.count(p.name)) order.push_back(p.name);
            pass_ms[p.name] += p.ms;
        }
        for (const effects::Renderer::PassDraws& d : renderer.pass_draws()) {
            if (!drawn.count(d.name)) drawn_order.push_back(d.name);
            drawn[d.name].draws += d.count.draws;
            drawn[d.name].triangles += d.count.triangles;
        }
    }
    std::string res = std::to_string(width) + "x" + std::to_string(height);
    for (const std::string& name : order)
        report.add({"render", "pass " + name + " @" + res, pass_ms[name] / frames, "ms"});
    for (const std::string& name : drawn_order) {
        report.add({"render", "pass " + name + " draws a frame @" + res, double(drawn[name].draws) / frames, "draws"});
        report.add({"render", "pass " + name + " triangles a frame @" + res, double(drawn[name].triangles) / frames,
                    "triangles"});
    }
    report.add({"render", "whole frame @" + res, frame_s * 1e3 / frames, "ms", std::nullopt, false,
                "profile mode: glFinish around each pass"});
}

}  // namespace

int bench_command(const std::vector<std::string>& argv) {
    Args args(argv, {"--json", "--only"}, {"--quick"});
    if (!args.positional().empty()) throw UsageError("bench takes no positional arguments");
    const bool quick = args.flag("--quick");
    // --only a,b: just those groups, to measure one effect without the rest.
    std::set<std::string> only;
    if (auto list = args.value("--only")) {
        std::stringstream in(*list);
        for (std::string g; std::getline(in, g, ',');) {
            if (std::find(kBenchGroups.begin(), kBenchGroups.end(), g) == kBenchGroups.end())
                throw UsageError("--only: unknown group '" + g + "' (" + bench_groups(", ") + ")");
            only.insert(g);
        }
    }
    auto runs = [&](const char* group) { return only.empty() || only.count(group) != 0; };
    BenchReport report;
    if (runs("sim")) {
        std::cerr << "bench: sim\n";
        bench_sim(report, quick ? 300 : 1800);
    }
    if (runs("replay")) {
        std::cerr << "bench: replay check\n";
        bench_replay_check(report, quick ? 300 : 1800);
        std::cerr << "bench: replay seek\n";
        bench_replay_seek(report, quick);
    }
    if (runs("water")) {
        std::cerr << "bench: water\n";
        bench_water(report, quick);
    }
    if (runs("dust")) {
        std::cerr << "bench: dust\n";
        bench_dust_cpu(report, quick);
    }
    if (runs("audio")) {
        std::cerr << "bench: audio\n";
        bench_audio(report, quick);
    }

    HeadlessContext context;
    if (runs("fluid")) {
        std::cerr << "bench: fluid\n";
        bench_fluid(report, quick);
    }
    if (runs("render")) {
        std::cerr << "bench: render (" << context.renderer() << ")\n";
        bench_render(report, 640, 360, quick ? 3 : 8);
        bench_render(report, 1280, 720, quick ? 3 : 8);
    }
    if (runs("energy")) {
        std::cerr << "bench: energy\n";
        bench_energy(report, quick);
    }
    if (runs("rain")) {
        std::cerr << "bench: rain\n";
        bench_rain(report, quick);
    }
    if (runs("dust")) {
        bench_dust_render(report, 640, 360, quick);
        bench_dust_render(report, 1280, 720, quick);
        bench_dust_render(report, 1280, 720, quick, DustBenchView::CloseUp);
    }
    if (runs("play")) bench_play(report, quick);
    if (runs("video")) {
#if SPINDRIFT_VIDEO
        std::cerr << "bench: video export\n";
        bench_video(report, quick);
#else
        std::cerr << "bench: video: not built (-DSPINDRIFT_VIDEO=OFF)\n";
#endif
    }
    report.add({"memory", "peak resident after 1280x720 frames", peak_resident_mib(), "MiB", 1024.0});

    report.print_table();
    if (auto path = args.value("--json")) {
        report.write_json(*path, context.renderer());
        std::cout << "wrote " << *path << "\n";
    }
    return kExitOk;
}

}  // namespace game
