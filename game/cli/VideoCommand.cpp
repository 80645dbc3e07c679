#include "game/cli/VideoCommand.h"

#include <cmath>
#include <iostream>

#include "game/cli/ExitCode.h"

#if SPINDRIFT_VIDEO
#include <cstdio>
#include <filesystem>

#include "game/capture/VideoExport.h"
#include "game/cli/Progress.h"
#include "game/level/LevelMemory.h"
#include "game/platform/HeadlessContext.h"
#include "game/replay/ReplayCheck.h"
#endif

namespace game {

#if SPINDRIFT_VIDEO
namespace {

namespace fs = std::filesystem;

// "WxH", each side even and within the encoder's bounds.
std::pair<int, int> parse_size(const std::string& text) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x')
        throw UsageError("--size must be WIDTHxHEIGHT, got '" + text + "'");
    if (w < kMinVideoSide || h < kMinVideoSide || w > kMaxVideoSide || h > kMaxVideoSide || w % 2 || h % 2)
        throw UsageError("--size " + text + ": each side must be even and " + std::to_string(kMinVideoSide) + ".." +
                         std::to_string(kMaxVideoSide) + " (H.264's 4:2:0 colour is halved each way)");
    return {w, h};
}

// A tick ("600") or seconds of replay time ("10s", "12.5s"), at most `total`.
uint32_t parse_time(const char* option, const std::string& text, uint32_t total) {
    const bool in_seconds = !text.empty() && text.back() == 's';
    const std::string number = in_seconds ? text.substr(0, text.size() - 1) : text;
    char* end = nullptr;
    const double value = std::strtod(number.c_str(), &end);
    const bool whole = in_seconds || std::floor(value) == value;
    if (number.empty() || *end || !std::isfinite(value) || value < 0 || !whole)
        throw UsageError(std::string(option) + " must be a tick (600) or seconds (10s), got '" + text + "'");
    const double ticks = in_seconds ? std::round(value * sim::kTickRateHz) : value;
    if (ticks > total)
        throw UsageError(std::string(option) + " " + text + " is past the replay's end (" + std::to_string(total) +
                         " ticks, " + std::to_string(total / sim::kTickRateHz) + " s)");
    return uint32_t(ticks);
}

int export_video(const Args& args) {
    for (const char* other : {"--check", "--update-goldens", "--require-goldens", "--exr"})
        if (args.flag(other)) throw UsageError(std::string(other) + " does not go with --video");
    for (const char* other : {"--frames", "--out", "--audio", "--settings"})
        if (args.value(other)) throw UsageError(std::string(other) + " does not go with --video");
    const fs::path out = *args.value("--video");
    if (!VideoEncoder::container_for(out)) throw UsageError("--video " + out.string() + ": the name must end in .mp4, .mov or .mkv");
    VideoFormat format;
    if (auto size = args.value("--size")) std::tie(format.width, format.height) = parse_size(*size);
    format.fps = args.integer("--fps", 60, 1, 1000);
    if (format.fps != 30 && format.fps != 60) throw UsageError("--fps must be 30 or 60");
    try {
        format.crf = args.integer("--quality", 18, 0, 51);
    } catch (const UsageError& e) {
        throw UsageError(std::string(e.what()) + " (with --video it is x264's CRF: lower is better and larger)");
    }
    format.sample_rate = audio::kSampleRate;

    const fs::path path = args.positional()[0];
    Replay replay = read_replay(path, ReadOptions{args.flag("--strict")});
    if (!replay.complete) std::cerr << path.string() << ": " << replay.cut_note << "\n";
    GameSession session = GameSession::open(args.value("--level").value_or(replay.header.level_id),
                                            args.integer("--threads", 1, 1, 64), replay.header.seed);
    if (auto why = replay_mismatch(replay, *session.world, session.level.content_hash)) {
        std::cerr << "error: cannot replay " << path.string() << ": " << *why << "\n";
        return kExitBadInput;
    }
    const uint32_t total = uint32_t(replay.inputs.size());
    VideoRange range;
    range.fps = format.fps;
    range.from = args.value("--from") ? parse_time("--from", *args.value("--from"), total) : 0;
    range.to = args.value("--to") ? parse_time("--to", *args.value("--to"), total) : total;
    if (range.frames() == 0)
        throw UsageError("--from " + std::to_string(range.from) + " --to " + std::to_string(range.to) +
                         ": not one frame at " + std::to_string(format.fps) + " fps (the range is in ticks of 1/" +
                         std::to_string(sim::kTickRateHz) + " s)");
    MemoryBudget memory = session.level.memory;
    charge_frame_memory(uint32_t(format.width), uint32_t(format.height), memory);

    // The file before anything renders: an unwritable path is refused at once.
    std::optional<VideoEncoder> encoder;
    try {
        encoder.emplace(out, format);
    } catch (const VideoError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitIo;
    }
    HeadlessContext context;
    OfflineSound sound(CameraTrack(replay.header.camera_shots, replay.header.tick_rate_hz));
    Progress progress("video " + out.filename().string(), range.frames(), "frames");
    VideoExportTimes times;
    try {
        times = export_replay_video(replay, session, *encoder, format, range, &sound,
                                    [&](uint32_t done) { progress.update(done); });
    } catch (const VideoError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitIo;
    }
    progress.finish();
    std::printf("%s: %u frames %dx%d at %d fps (ticks %u..%u of %u, %.2f s), H.264 (%s, CRF %d) and AAC sound\n",
                out.string().c_str(), range.frames(), format.width, format.height, format.fps, range.frame_tick(0),
                range.frame_tick(range.frames() - 1), total, double(range.frames()) / format.fps,
                encoder->video_codec().c_str(), format.crf);
    std::printf("  took %.1f s: rendering %.1f s, encoding %.1f s, sound %.1f s, sim %.1f s\n", times.total,
                times.render, times.encode, times.sound, times.sim);
    return kExitOk;
}

}  // namespace
#endif

std::optional<int> video_export_if_asked(const Args& args) {
    if (!args.value("--video")) {
        for (const char* option : kVideoOptions)
            if (args.value(option)) throw UsageError(std::string(option) + " belongs to --video OUT.mp4");
        return std::nullopt;
    }
#if SPINDRIFT_VIDEO
    return export_video(args);
#else
    std::cerr << "error: this build has no video export (configured with -DSPINDRIFT_VIDEO=OFF)\n";
    return kExitPlatform;
#endif
}

}  // namespace game
