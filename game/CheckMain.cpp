// spindrift-check REPLAY... [--threads N] [--strict] [--snapshots N]
// Replays each recording without rendering and checks the world hash after every tick:
// `spindrift replay R --headless --check --frames none` in a program with no GL, EGL,
// window or image library, so that it builds wherever the sim does (another CPU, a
// compiler the game is not built with). Exit codes as spindrift's: 0 every hash matched,
// 1 a desync, 2 bad command line, 3 a replay or level that cannot be used, 4 the sim
// refused this machine's floating-point environment. --snapshots N also restores a
// snapshot taken every N ticks into a fresh world and checks it steps on exactly
// (game/replay/SnapshotCheck.h).
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "game/cli/Args.h"
#include "game/cli/ExitCode.h"
#include "game/level/LevelLoader.h"
#include "game/replay/ObjectiveSummary.h"
#include "game/replay/ReplayCheck.h"
#include "game/replay/ReplayReader.h"
#include "game/replay/SnapshotCheck.h"
#include "game/session/GameSession.h"
#include "sim/core/FloatEnvironment.h"
#include "sim/core/StateArchive.h"

namespace {

constexpr const char* kUsage =
    "usage: spindrift-check REPLAY... [--threads N] [--strict] [--snapshots N]\n"
    "Replays each file without rendering and checks the world hash after every tick.\n"
    "  --threads N  sim threads (1-64, default 1): the hashes are the same for any count\n"
    "  --strict     refuse a replay whose recording was cut (its .partial prefix)\n"
    "  --snapshots N  also snapshot the world every N ticks (1-100000), restore each into a\n"
    "               fresh world and check it steps on to the next with the recorded hashes\n";

// One replay: 0 when every hash matched, else the exit code it deserves.
int check_one(const std::string& path, int threads, bool strict, int snapshots) {
    using namespace game;
    const Replay replay = read_replay(path, ReadOptions{strict});
    if (!replay.complete) std::cerr << path << ": " << replay.cut_note << "\n";
    // No fibre reader: the fibre image is the renderer's, and this program reads no images.
    GameSession session = GameSession::start(load_level(replay.header.level_id, nullptr), threads, replay.header.seed);
    if (auto why = replay_mismatch(replay, *session.world, session.level.content_hash)) {
        std::cerr << "error: cannot replay " << path << ": " << *why << "\n";
        return kExitBadInput;
    }
    if (snapshots > 0) {
        const SnapshotCheckResult r =
            check_snapshots(replay, session.world->level(), session.level.content_hash, uint32_t(snapshots), threads);
        if (r.failure) {
            std::cout << path << ": SNAPSHOT CHECK FAILED: " << *r.failure << "\n";
            return kExitCheckFailed;
        }
        std::cout << path << ": snapshots every " << snapshots << " ticks: " << r.snapshots
                  << " restored into fresh worlds, " << r.ticks_restepped
                  << " ticks stepped on from them, every hash and the next snapshot matched (largest "
                  << r.largest_bytes / 1024 << " KiB)\n";
    }
    ReplayChecker checker(replay);
    sim::World& world = *session.world;
    for (const sim::TickInput& input : replay.inputs) {
        world.step(input);
        if (auto divergence = checker.after_step(world)) {
            std::cout << path << ": DESYNC at " << divergence->message << "\n";
            return kExitCheckFailed;
        }
    }
    std::cout << path << ": " << replay.inputs.size() << " ticks, " << checker.hashes_checked()
              << " hash checks, check passed" << (replay.complete ? "" : " (on the replay's complete prefix)")
              << " (" << threads << (threads == 1 ? " thread" : " threads") << ")\n";
    // The objectives as the ticks left them, as `spindrift replay` prints them: the
    // checked hashes confirm them.
    for (const std::string& line : objective_summary_lines(world)) std::cout << "  " << line << "\n";
    return game::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace game;
    std::vector<std::string> argv_list(argv + 1, argv + argc);
    for (const std::string& a : argv_list)
        if (a == "--help" || a == "-h") {
            std::cout << kUsage;
            return kExitOk;
        }
    int threads = 1;
    bool strict = false;
    int snapshots = 0;
    std::vector<std::string> files;
    try {
        Args args(argv_list, {"--threads", "--snapshots"}, {"--strict"});
        threads = args.integer("--threads", 1, 1, 64);
        strict = args.flag("--strict");
        snapshots = args.integer("--snapshots", 0, 1, 100000);
        files = args.positional();
        if (files.empty()) throw UsageError("name at least one replay file");
    } catch (const UsageError& e) {
        std::cerr << "error: " << e.what() << "\n" << kUsage;
        return kExitUsage;
    }
    int bad_input = 0, desynced = 0;
    for (const std::string& file : files) {
        int code = kExitOk;
        try {
            code = check_one(file, threads, strict, snapshots);
        } catch (const ReplayError& e) {
            std::cerr << "error: " << e.what() << "\n";
            code = kExitBadInput;
        } catch (const sim::SnapshotError& e) {
            std::cerr << "error: " << file << ": " << e.what() << "\n";
            code = kExitCheckFailed;
        } catch (const LevelError& e) {
            std::cerr << "error: " << e.what() << "\n";
            code = kExitBadInput;
        } catch (const sim::FloatEnvironmentError& e) {
            std::cerr << "error: " << e.what() << "\n";
            return kExitPlatform;
        }
        if (code == kExitBadInput) ++bad_input;
        if (code == kExitCheckFailed) ++desynced;
    }
    if (bad_input || desynced) {
        std::cout << "spindrift-check: " << desynced << " of " << files.size() << " replays desynced, " << bad_input
                  << " could not be checked\n";
        return bad_input ? kExitBadInput : kExitCheckFailed;
    }
    if (files.size() > 1) std::cout << "spindrift-check: all " << files.size() << " replays match, tick for tick\n";
    return kExitOk;
}
