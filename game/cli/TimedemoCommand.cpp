// spindrift timedemo REPLAY [--size WxH] [--quality low|medium|high|auto] [--scale S] [--json FILE]
//                           [--headless] [--threads N]
#include <charconv>
#include <filesystem>
#include <iostream>
#include <memory>

#include "game/cli/Args.h"
#include "game/cli/Commands.h"
#include "game/cli/ExitCode.h"
#include "game/cli/QualityOption.h"
#include "game/level/LevelMemory.h"
#include "game/platform/HeadlessContext.h"
#include "game/play/OffscreenScreen.h"
#include "game/play/Timedemo.h"
#include "game/play/WindowScreen.h"
#include "game/replay/ReplayCheck.h"

namespace game {

namespace fs = std::filesystem;

namespace {

constexpr int kMinSide = 16, kMaxWidth = 7680, kMaxHeight = 4320;

Screen::Size size_option(const Args& args) {
    const std::string text = args.value("--size").value_or("1280x720");
    const auto bad = [&] {
        return UsageError("--size must be WIDTHxHEIGHT, from " + std::to_string(kMinSide) + "x" +
                          std::to_string(kMinSide) + " to " + std::to_string(kMaxWidth) + "x" +
                          std::to_string(kMaxHeight) + ", got '" + text + "'");
    };
    const size_t x = text.find('x');
    if (x == std::string::npos) throw bad();
    Screen::Size size;
    const char* end = text.data() + text.size();
    auto [w_end, w_ec] = std::from_chars(text.data(), text.data() + x, size.width);
    auto [h_end, h_ec] = std::from_chars(text.data() + x + 1, end, size.height);
    if (w_ec != std::errc() || w_end != text.data() + x || h_ec != std::errc() || h_end != end) throw bad();
    if (size.width < kMinSide || size.height < kMinSide || size.width > kMaxWidth || size.height > kMaxHeight)
        throw bad();
    return size;
}

// --scale S: a fixed render scale in [0.25, 1] (auto: instead of its controller).
std::optional<float> scale_option(const Args& args) {
    const std::optional<std::string> text = args.value("--scale");
    if (!text) return std::nullopt;
    float scale = 0.0f;
    const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), scale);
    if (ec != std::errc() || end != text->data() + text->size() || !(scale >= 0.25f && scale <= 1.0f))
        throw UsageError("--scale takes a render scale from 0.25 to 1, not \"" + *text + "\"");
    return scale;
}

}  // namespace

int timedemo_command(const std::vector<std::string>& argv) {
    Args args(argv, {"--size", "--quality", "--scale", "--json", "--threads"}, {"--headless"});
    if (args.positional().size() != 1) throw UsageError("timedemo takes one replay file");
    const fs::path path = args.positional()[0];
    const Screen::Size size = size_option(args);
    const QualityChoice quality = quality_option(args);
    const int threads = args.integer("--threads", 1, 1, 64);
    const std::optional<float> scale = scale_option(args);

    const Replay replay = read_replay(path, ReadOptions{});
    if (!replay.complete) std::cerr << path.string() << ": " << replay.cut_note << "\n";
    GameSession session = GameSession::open(replay.header.level_id, threads, replay.header.seed);
    if (auto why = replay_mismatch(replay, *session.world, session.level.content_hash)) {
        std::cerr << "error: cannot play " << path.string() << ": " << *why << "\n";
        return kExitBadInput;
    }
    MemoryBudget memory = session.level.memory;
    charge_frame_memory(uint32_t(size.width), uint32_t(size.height), memory);

    // A window when there is a display (without vsync: frames as fast as they come),
    // else an offscreen target in a headless context.
    std::unique_ptr<HeadlessContext> context;
    std::unique_ptr<Screen> screen;
    if (display_available() && !args.flag("--headless")) {
        screen = std::make_unique<WindowScreen>(Window::Options{size.width, size.height, "Spindrift - timedemo", false});
    } else {
        context = std::make_unique<HeadlessContext>();
        screen = std::make_unique<OffscreenScreen>(size.width, size.height);
    }
    std::cerr << "timedemo: playing " << path.filename().string() << " in real time ("
              << replay.inputs.size() / sim::kTickRateHz << " s)\n";
    const TimedemoRun run = run_timedemo(replay, path.filename().string(), session, *screen, quality, scale);
    const TimedemoSummary summary = summarise(run);
    print_timedemo(run, summary);
    if (auto json = args.value("--json")) {
        write_timedemo_json(*json, run, summary);
        std::cout << "wrote " << *json << "\n";
    }
    if (run.desync) return kExitCheckFailed;
    return kExitOk;
}

}  // namespace game
