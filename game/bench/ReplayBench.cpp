#include "game/bench/ReplayBench.h"

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "game/bench/BenchSupport.h"
#include "game/replay/InputScript.h"
#include "game/replay/KeyframeStore.h"
#include "game/replay/ReplayReader.h"
#include "game/replay/ReplaySeeker.h"
#include "game/replay/ReplayWriter.h"
#include "game/session/GameSession.h"
#include "game/session/ReplayHeaderFor.h"

namespace game {

namespace {

// The car to the boat (as replays/harbour_goals.script), then the boat round its course
// again and again, a stone every 7 s, a float every 13 s, a shot every 11 s.
std::string long_script(uint32_t ticks) {
    std::ostringstream s;
    s << "level harbour\n"
         "0 hold throttle steer=-0.50\n24 hold throttle\n192 hold\n234 hold brake\n270 hold brake steer=-0.50\n"
         "276 hold brake\n300 hold\n360 hold throttle steer_left\n426 hold brake\n456 hold\n"
         "522 tap switch_vehicle\n";
    const std::pair<uint32_t, const char*> lap[] = {
        {0, "throttle steer=0.25"}, {216, "throttle steer=0.50"}, {246, "throttle steer=0.75"},
        {270, "throttle steer_left"}, {426, "throttle steer=0.75"}, {486, "throttle steer=0.50"},
        {528, "throttle steer=0.75"}, {630, "throttle steer_left"}, {678, "throttle steer=0.75"},
        {840, "throttle steer_left"}, {864, "throttle steer=0.75"}, {972, "throttle steer=0.50"},
        {990, "throttle steer=0.25"}};
    std::vector<std::pair<uint32_t, std::string>> lines;
    for (uint32_t at = 534; at < ticks; at += 1026)
        for (const auto& [t, what] : lap)
            if (at + t < ticks) lines.push_back({at + t, std::string("hold ") + what});
    for (uint32_t t = 600; t < ticks; ++t) {
        if (t % 420 == 0) lines.push_back({t, "tap throw_heavy"});
        else if (t % 780 == 0) lines.push_back({t, "tap throw_light"});
        else if (t % 660 == 0) lines.push_back({t, "tap fire"});
    }
    std::stable_sort(lines.begin(), lines.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    uint32_t last = ~0u;
    for (const auto& [t, what] : lines) {
        if (t == last) continue;  // one line a tick: the hold wins over a tap
        s << t << " " << what << "\n";
        last = t;
    }
    s << ticks << " end\n";
    return s.str();
}

// This thread's CPU time (the sim runs on it alone): on a machine shared with other work
// the wall clock also counts the time other processes had the cores.
double cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

double percentile(std::vector<double> v, double p) {
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, size_t(p * double(v.size() - 1) + 0.5))];
}

}  // namespace

void bench_replay_seek(BenchReport& report, bool quick) {
    const uint32_t ticks = quick ? 60 * 60 : 10 * 60 * 60;
    const std::string minutes = fmt("%.0f-minute", ticks / 3600.0);
    // Recorded as `spindrift record` does, to a temporary file, and read back.
    const InputScript script = parse_script(long_script(ticks), "bench script");
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / fmt("spindrift_bench_%d.replay", int(::getpid()));
    auto start = BenchClock::now();
    {
        // No fibre image: nothing is rendered.
        GameSession s = GameSession::start(load_level("harbour", nullptr), 1);
        ReplayWriter writer = ReplayWriter::create(file, replay_header_for(s, 480, 270, {}));
        for (const sim::TickInput& in : script.inputs) {
            s.world->step(in);
            writer.append(in, s.world->hash());
        }
        writer.finish();
    }
    const double record_s = seconds_since(start);
    const Replay replay = read_replay(file, ReadOptions{true});
    std::filesystem::remove(file);

    GameSession s = GameSession::start(load_level("harbour", nullptr), 1, replay.header.seed);
    KeyframeStore keyframes(s.level.content_hash);
    ReplaySeeker seeker(replay.inputs, *s.world, keyframes);
    start = BenchClock::now();
    seeker.seek(seeker.ticks());  // watched once to the end: every keyframe exists
    const double first_pass_s = seconds_since(start);

    // Seeks to ticks spread at random over the replay, from wherever the last left it.
    uint64_t lcg = 0x5eed;
    auto next_tick = [&] {
        lcg = lcg * 6364136223846793005ull + 1442695040888963407ull;
        return (lcg >> 33) % (seeker.ticks() + 1);
    };
    std::vector<double> seek_ms, back_ms, seek_cpu, back_cpu;
    const int samples = quick ? 20 : 60;
    for (int i = 0; i < samples; ++i) {
        const uint64_t to = next_tick();
        auto t0 = BenchClock::now();
        const double c0 = cpu_ms();
        seeker.seek(to);
        seek_cpu.push_back(cpu_ms() - c0);
        seek_ms.push_back(ms_since(t0));
        if (to > 0 && s.world->hash().world != replay.tick_world_hashes[size_t(to) - 1])
            throw std::runtime_error(fmt("bench: the seek to tick %llu reached another world", (unsigned long long)to));
    }
    // One tick back, from ticks that were played to (not sought), as a viewer paused would.
    for (int i = 0; i < samples; ++i) {
        const uint64_t to = std::max<uint64_t>(next_tick(), 2);
        seeker.seek(to >= 40 ? to - 40 : 0);
        seeker.seek(to);
        auto t0 = BenchClock::now();
        const double c0 = cpu_ms();
        seeker.seek(to - 1);
        back_cpu.push_back(cpu_ms() - c0);
        back_ms.push_back(ms_since(t0));
    }
    const double mib = double(keyframes.compressed_bytes()) / (1024.0 * 1024.0);
    const std::string on = fmt("%s replay (%u ticks) recorded from a script in %.1f s; load average %s",
                               minutes.c_str(), ticks, record_s, load_average().c_str());
    report.add({"replay", "seek anywhere p95", percentile(seek_ms, 0.95), "ms", 250.0, false,
                fmt("%d seeks, max %.0f ms, median %.0f ms, CPU time p95 %.0f ms; ", samples, percentile(seek_ms, 1.0),
                    percentile(seek_ms, 0.5), percentile(seek_cpu, 0.95)) + on});
    report.add({"replay", "one tick back p95", percentile(back_ms, 0.95), "ms", 60.0, false,
                fmt("%d steps back, max %.0f ms, CPU time p95 %.0f ms; raw snapshots every %u ticks within the current %u: %.1f MiB",
                    samples, percentile(back_ms, 1.0), percentile(back_cpu, 0.95), 30u, keyframes.interval(),
                    double(seeker.near_bytes()) / (1024.0 * 1024.0))});
    report.add({"replay", "keyframe memory for " + minutes, mib, "MiB", quick ? 64.0 / 10.0 : 64.0, false,
                fmt("%zu keyframes every %u ticks, zstd level 1, %.1f MiB raw; first pass to the end %.1f s",
                    keyframes.count(), keyframes.interval(), double(keyframes.raw_bytes()) / (1024.0 * 1024.0),
                    first_pass_s)});
}

}  // namespace game
