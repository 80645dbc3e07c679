#include "game/bench/AudioBench.h"

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <vector>

#include "game/DataPaths.h"
#include "game/audio/SessionSound.h"
#include "game/bench/BenchSupport.h"
#include "game/replay/ReplayReader.h"
#include "game/session/GameSession.h"
#include "game/session/TickDriver.h"

namespace game {

namespace fs = std::filesystem;

namespace {

constexpr int kBlock = 512;
constexpr int kFramesPerTick = audio::kSampleRate / sim::kTickRateHz;

double thread_cpu_ms() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
}

struct AudioRun {
    std::string name;
    double mean_ms = 0.0, p99_ms = 0.0, max_ms = 0.0;
    double mean_voices = 0.0;
    int max_voices = 0;
    size_t blocks = 0;
};

AudioRun run(const fs::path& path) {
    const Replay replay = read_replay(path, ReadOptions{});
    GameSession session = GameSession::open(replay.header.level_id, 1, replay.header.seed);
    SessionSound sound(CameraTrack(replay.header.camera_shots, replay.header.tick_rate_hz));
    TickDriver driver(*session.world);
    std::vector<double> ms;
    std::vector<float> block(2 * kBlock);
    long owed = 0;  // frames of sound the ticks so far have asked for and the blocks not yet given
    AudioRun r;
    r.name = path.stem().string();
    double voices = 0.0;
    // As the live output does: blocks of 512 follow the ticks' 800 frames each.
    driver.listen([&](const sim::World& world, sim::TickInput) {
        sound.after_tick(world);
        owed += kFramesPerTick;
        while (owed >= kBlock) {
            const double start = thread_cpu_ms();
            sound.mixer().render(block.data(), kBlock);
            ms.push_back(thread_cpu_ms() - start);
            const int live = sound.mixer().live_voices();
            voices += live;
            r.max_voices = std::max(r.max_voices, live);
            owed -= kBlock;
        }
    });
    for (const sim::TickInput& input : replay.inputs) driver.step(input);
    r.blocks = ms.size();
    if (ms.empty()) return r;
    double sum = 0.0;
    for (double m : ms) sum += m;
    r.mean_ms = sum / double(ms.size());
    r.mean_voices = voices / double(ms.size());
    std::sort(ms.begin(), ms.end());
    r.p99_ms = ms[std::min(ms.size() - 1, size_t(0.99 * double(ms.size())))];
    r.max_ms = ms.back();
    return r;
}

}  // namespace

void bench_audio(BenchReport& report, bool quick) {
    const fs::path dir = data_dir() / "replays";
    std::vector<fs::path> paths;
    if (quick) paths.push_back(dir / "harbour_rain.replay");
    else
        for (const fs::directory_entry& e : fs::directory_iterator(dir))
            if (e.path().extension() == ".replay") paths.push_back(e.path());
    std::sort(paths.begin(), paths.end());
    std::vector<AudioRun> runs;
    for (const fs::path& p : paths) runs.push_back(run(p));
    // The targets are judged on the busiest replay: the one whose blocks cost most.
    const auto busiest = std::max_element(runs.begin(), runs.end(),
                                          [](const AudioRun& a, const AudioRun& b) { return a.mean_ms < b.mean_ms; });
    for (const AudioRun& r : runs) {
        const bool judged = &r == &*busiest;
        const std::string note = fmt("%zu blocks, voices mean %.1f max %d, worst block %.3f ms%s", r.blocks,
                                     r.mean_voices, r.max_voices, r.max_ms, judged ? "; the busiest replay" : "");
        report.add({"audio", "mix+synth per 512-frame block mean " + r.name, r.mean_ms, "ms",
                    judged ? std::optional<double>(0.5) : std::nullopt, false, note});
        report.add({"audio", "mix+synth per 512-frame block p99 " + r.name, r.p99_ms, "ms",
                    judged ? std::optional<double>(2.0) : std::nullopt, false, note});
    }
}

}  // namespace game
