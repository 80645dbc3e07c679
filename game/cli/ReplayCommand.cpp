// spindrift replay FILE [--headless] [--check] [--frames LIST] [--out DIR] [--exr]
//                      [--update-goldens] [--require-goldens] [--strict] [--threads N]
//                      [--level NAME|PATH] [--audio OUT.wav] (headless)
//                      [--quality low|medium|high|auto] [--record FILE] (in a window)
//                      [--video OUT.mp4 ...] (game/cli/VideoCommand.h)
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>

#include "effects/Renderer.h"
#include "game/audio/ReplaySound.h"
#include "game/capture/FrameCapture.h"
#include "game/capture/FrameCompare.h"
#include "game/capture/ImageFiles.h"
#include "game/cli/Args.h"
#include "game/cli/Commands.h"
#include "game/cli/ExitCode.h"
#include "game/cli/Progress.h"
#include "game/cli/QualityOption.h"
#include "game/cli/SettingsOption.h"
#include "game/cli/VideoCommand.h"
#include "game/level/LevelMemory.h"
#include "game/platform/HeadlessContext.h"
#include "game/play/PlayMode.h"
#include "game/replay/CameraTrack.h"
#include "game/replay/FrameSelection.h"
#include "game/replay/ObjectiveSummary.h"
#include "game/replay/ReplayCheck.h"
#include "game/session/GameSession.h"
#include "game/session/TickDriver.h"

namespace game {

namespace fs = std::filesystem;

namespace {

std::string frame_name(uint32_t tick, const char* suffix) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "tick_%06u%s", tick, suffix);
    return buf;
}

// A golden that is black or one flat colour tests nothing.
std::optional<std::string> flat_frame_problem(const ImageRGBA8& image) {
    ImageStats s = image_stats(image);
    if (s.mean_luma < 0.02) return "the frame is black (mean luma " + std::to_string(s.mean_luma) + ")";
    if (s.luma_stddev < 0.01) return "the frame is flat (luma deviation " + std::to_string(s.luma_stddev) + ")";
    return std::nullopt;
}

struct FrameOutcome {
    bool ok = true;
    std::string line;
};

}  // namespace

int replay_command(const std::vector<std::string>& argv) {
    std::set<std::string> with_value{"--frames", "--out", "--threads", "--level", "--quality", "--settings", "--audio", "--record"};
    with_value.insert(std::begin(kVideoOptions), std::end(kVideoOptions));
    Args args(argv, with_value, {"--headless", "--check", "--update-goldens", "--require-goldens", "--strict", "--exr"});
    if (args.positional().size() != 1) throw UsageError("replay takes one replay file");
    if (std::optional<int> exported = video_export_if_asked(args)) return *exported;
    const fs::path path = args.positional()[0];
    const bool check = args.flag("--check");
    const bool update = args.flag("--update-goldens");
    // A new recording has no goldens yet: its hashes are still checked, its frames are
    // not, and the check says so. The bundled replays' checks require them.
    const bool require_goldens = args.flag("--require-goldens");
    const int threads = args.integer("--threads", 1, 1, 64);
    (void)quality_option(args);  // a bad --quality is refused before the replay is read
    FrameSelection frames = args.value("--frames") ? FrameSelection::parse(*args.value("--frames")) : FrameSelection{};

    Replay replay = read_replay(path, ReadOptions{args.flag("--strict")});
    if (!replay.complete) std::cerr << path.string() << ": " << replay.cut_note << "\n";
    const ReplayHeader& header = replay.header;
    GameSession session = GameSession::open(args.value("--level").value_or(header.level_id), threads, header.seed);
    if (auto why = replay_mismatch(replay, *session.world, session.level.content_hash)) {
        std::cerr << "error: cannot replay " << path.string() << ": " << *why << "\n";
        return kExitBadInput;
    }
    const uint32_t total = uint32_t(replay.inputs.size());
    for (uint32_t t : frames.ticks)
        if (t > total)
            throw UsageError("--frames names tick " + std::to_string(t) + ", past the replay's end (" +
                             std::to_string(total) + " ticks)");

    const std::optional<std::string> audio_out = args.value("--audio");
    if (audio_out && !args.flag("--headless")) throw UsageError("--audio renders the sound offline: add --headless");
    if (args.value("--record") && args.flag("--headless"))
        throw UsageError("--record keeps a take over in the window's viewer: leave out --headless");
    if (!args.flag("--headless")) {
        if (display_available())
            return play_replay_in_window(replay, session, player_settings(args),
                                         ViewerOptions{.record = args.value("--record"), .threads = threads});
        if (args.value("--record")) throw UsageError("--record takes over in a window, and there is no display");
        std::cerr << "no display: replaying headless\n";
    }

    const std::set<uint32_t> checkpoints(header.checkpoints.begin(), header.checkpoints.end());
    bool any_frames = frames.kind == FrameSelection::Kind::All || frames.kind == FrameSelection::Kind::List ||
                      (frames.kind == FrameSelection::Kind::Checkpoints && !checkpoints.empty());
    const fs::path golden_dir = path.parent_path() / path.stem();
    const fs::path out_dir = args.value("--out") ? fs::path(*args.value("--out")) : fs::path("spindrift-out") / path.stem();

    std::unique_ptr<HeadlessContext> context;
    std::unique_ptr<effects::Renderer> renderer;
    std::unique_ptr<FrameCapture> capture;
    if (any_frames) {
        // The replay's frame size against the level's memory budget, before any target exists.
        MemoryBudget memory = session.level.memory;
        charge_frame_memory(header.frame_width, header.frame_height, memory);
        context = std::make_unique<HeadlessContext>();
        renderer = std::make_unique<effects::Renderer>(session.level.scene, *session.world);
        // Only the EXR reads the scene's normals.
        renderer->write_normals(args.flag("--exr") && args.value("--out"));
        capture = std::make_unique<FrameCapture>(int(header.frame_width), int(header.frame_height));
    }

    const CameraTrack cameras(header.camera_shots, header.tick_rate_hz);
    // The sound file is opened (as OUT.wav.partial) before anything renders: an
    // unwritable path is refused at once.
    std::optional<audio::WavWriter> wav;
    std::unique_ptr<OfflineSound> sound;
    if (audio_out) {
        try {
            wav.emplace(*audio_out, audio::kSampleRate);
        } catch (const audio::WavError& e) {
            std::cerr << "error: " << e.what() << "\n";
            return kExitIo;
        }
        sound = std::make_unique<OfflineSound>(cameras);
    }
    ReplayChecker checker(replay);
    std::vector<FrameOutcome> outcomes;
    size_t missing_goldens = 0;
    size_t frames_written = 0;
    std::optional<Divergence> divergence;
    Progress progress("replay " + path.filename().string(), total, "ticks");
    sim::World& world = *session.world;
    TickDriver driver(world);
    if (check) driver.listen([&](const sim::World& w, sim::TickInput) { divergence = checker.after_step(w); });
    if (sound)
        driver.listen([&](const sim::World& w, sim::TickInput) {
            const std::vector<float>& samples = sound->after_tick(w);
            wav->append(samples.data(), kFramesPerTick);
        });
    for (uint32_t i = 0; i < total; ++i) {
        try {
            driver.step(replay.inputs[i]);
        } catch (const audio::WavError& e) {
            std::cerr << "error: " << e.what() << "\n";
            return kExitIo;
        }
        const uint32_t tick = uint32_t(world.tick());
        if (divergence) break;
        progress.update(tick);
        if (!frames.wants(tick, checkpoints)) continue;

        effects::FramePoses poses = effects::capture_poses(world);
        poses.camera = cameras.view_at(tick, poses.camera);
        renderer->render(world, capture->output(), poses);
        ImageRGBA8 image = capture->read();
        if (args.value("--out")) {
            write_png(out_dir / frame_name(tick, ".png"), image);
            if (args.flag("--exr")) FrameCapture::write_scene_exr(out_dir / frame_name(tick, ".exr"), renderer->targets(), 0.1f, 4000.0f);
            ++frames_written;
        }
        if (!checkpoints.count(tick) || !(check || update)) continue;
        const fs::path golden = golden_dir / frame_name(tick, ".png");
        if (update) {
            if (auto why = flat_frame_problem(image)) {
                outcomes.push_back({false, "tick " + std::to_string(tick) + ": not storing a golden: " + *why});
                continue;
            }
            write_png(golden, image);
            outcomes.push_back({true, "tick " + std::to_string(tick) + ": golden written to " + golden.string()});
            continue;
        }
        if (!fs::exists(golden)) {
            ++missing_goldens;
            outcomes.push_back({!require_goldens, "tick " + std::to_string(tick) + ": no golden " + golden.string() +
                                                      (require_goldens ? "" : ", frame not checked") +
                                                      " (make it with --update-goldens)"});
            continue;
        }
        ImageRGBA8 want = read_png(golden);
        CompareResult r = compare_frames(image, want);
        std::optional<std::string> flat = flat_frame_problem(want);
        if (r.passed && !flat) {
            outcomes.push_back({true, "tick " + std::to_string(tick) + ": ok (" + r.summary + ")"});
            continue;
        }
        fs::path actual = out_dir / frame_name(tick, ".actual.png"), diff = out_dir / frame_name(tick, ".diff.png");
        write_png(actual, image);
        write_png(diff, difference_image(image, want));
        outcomes.push_back({false, "tick " + std::to_string(tick) + ": FAILED: " + (flat ? "golden: " + *flat : r.summary) +
                                       "; actual " + actual.string() + ", difference " + diff.string()});
    }
    progress.finish();

    bool ok = !divergence;
    std::cout << path.string() << ": " << total << " ticks";
    if (check) std::cout << ", " << checker.hashes_checked() << " hash checks";
    std::cout << "\n";
    // The objectives as the ticks left them: with --check they follow from the checked hashes.
    if (!divergence)
        for (const std::string& line : objective_summary_lines(world)) std::cout << "  " << line << "\n";
    for (const FrameOutcome& o : outcomes) {
        std::cout << "  " << o.line << "\n";
        ok = ok && o.ok;
    }
    if (frames_written) std::cout << "  " << frames_written << " frames written to " << out_dir.string() << "\n";
    if (wav && !divergence) {
        try {
            wav->finish();
        } catch (const audio::WavError& e) {
            std::cerr << "error: " << e.what() << "\n";
            return kExitIo;
        }
        std::cout << "  sound: " << wav->frames() << " frames at " << audio::kSampleRate << " Hz written to " << *audio_out
                  << "\n";
    }
    if (divergence) {
        std::cout << "DESYNC at " << divergence->message << "\n";
        return kExitCheckFailed;
    }
    if (!ok) {
        std::cout << "FAILED\n";
        return update ? kExitIo : kExitCheckFailed;
    }
    std::cout << (check ? "check passed" : "done") << (replay.complete ? "" : " (on the replay's complete prefix)");
    if (missing_goldens)
        std::cout << " (" << missing_goldens << " of " << checkpoints.size()
                  << " checkpoints have no golden: their frames were not checked; --require-goldens fails then)";
    std::cout << "\n";
    return kExitOk;
}

}  // namespace game
