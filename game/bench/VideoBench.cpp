#include "game/bench/VideoBench.h"

#include <unistd.h>

#include <algorithm>
#include <ctime>
#include <filesystem>

#include "game/DataPaths.h"
#include "game/bench/BenchSupport.h"
#include "game/bench/TrivialFill.h"
#include "game/capture/VideoExport.h"

namespace game {

namespace fs = std::filesystem;

namespace {

double process_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

}  // namespace

void bench_video(BenchReport& report, bool quick) {
    const Replay replay = read_replay(data_dir() / "replays" / "harbour_goals.replay", ReadOptions{});
    GameSession session = GameSession::open(replay.header.level_id, 1, replay.header.seed);
    const VideoFormat format{.width = 1280, .height = 720, .fps = 60, .crf = 18, .sample_rate = audio::kSampleRate};
    const VideoRange range{.from = 0, .to = quick ? 60u : 240u, .fps = format.fps};
    const fs::path out = fs::temp_directory_path() / ("spindrift_video_bench_" + std::to_string(getpid()) + ".mp4");
    OfflineSound sound(CameraTrack(replay.header.camera_shots, replay.header.tick_rate_hz));
    const double cpu_start = process_cpu_seconds();
    VideoExportTimes times;
    {
        VideoEncoder encoder(out, format);
        times = export_replay_video(replay, session, encoder, format, range, &sound);
    }
    const double cpu = process_cpu_seconds() - cpu_start;
    const uintmax_t bytes = fs::file_size(out);
    fs::remove(out);
    const double frames = range.frames();
    // The machine's speed at the time (it may be shared): a trivial fill at the size.
    const double fill_ms = median_ms(trivial_fill_samples(format.width, format.height, 9));
    const std::string what = fmt("%u frames of harbour_goals, H.264 CRF %d and AAC", range.frames(), format.crf);
    report.add({"video", "export @1280x720 60 fps", frames / times.total, "frames/s", std::nullopt, true,
                what + fmt(", %.0f s of CPU time for %.1f s of wall time", cpu, times.total)});
    report.add({"video", "encoder share of the export", 100.0 * times.encode / times.total, "%", std::nullopt, false,
                "wall time in the encoder's calls (x264's own threads run beside the rendering)"});
    report.add({"video", "render and read back per frame", 1e3 * times.render / frames, "ms"});
    report.add({"video", "export per frame in fills", 1e3 * times.total / frames / std::max(fill_ms, 1e-6), "fills",
                std::nullopt, false, fmt("a trivial 1280x720 fill took %.2f ms after the export", fill_ms)});
    report.add({"video", "encode per frame", 1e3 * times.encode / frames, "ms"});
    report.add({"video", "file size per second of video", double(bytes) / 1024.0 / (frames / format.fps), "KiB"});
}

}  // namespace game
