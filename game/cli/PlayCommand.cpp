// spindrift play [--level NAME|PATH] [--record FILE] [--quality low|medium|high|auto] [--threads N]
//                [--settings FILE] [--fullscreen|--windowed] [--ghost REPLAY]
#include <filesystem>
#include <iostream>

#include "game/DataPaths.h"
#include "game/cli/Args.h"
#include "game/cli/Commands.h"
#include "game/cli/ExitCode.h"
#include "game/cli/QualityOption.h"
#include "game/cli/SettingsOption.h"
#include "game/play/PlayMode.h"
#include "game/replay/ReplayCheck.h"
#include "game/replay/ReplayReader.h"
#include "game/session/GameSession.h"

namespace game {

namespace fs = std::filesystem;

namespace {

// Without a display the bundled demo replay is rendered headless instead, so that
// `play` still shows something on a server or in CI.
int render_demo_headless(const Args& args) {
    std::cout << "no display: rendering the bundled demo replay headless instead" << std::endl;
    if (args.value("--record") || args.value("--level") || args.value("--ghost"))
        std::cerr << "note: --level, --record and --ghost need a window; they are not used for the demo replay\n";
    const fs::path demo = data_dir() / "replays" / "harbour_drive.replay";
    if (!fs::exists(demo)) {
        std::cerr << "error: the bundled demo replay " << demo.string()
                  << " does not exist (SPINDRIFT_DATA names the folder holding replays/)\n";
        return kExitBadInput;
    }
    const fs::path out_dir = fs::path("spindrift-out") / "demo";
    // Its length picks the frames; replay_command reads it again and reports any problem.
    const Replay replay = read_replay(demo, ReadOptions{});
    std::vector<std::string> replay_args =
        demo_replay_args(demo, uint32_t(replay.inputs.size()), out_dir);
    if (auto threads = args.value("--threads")) {
        replay_args.push_back("--threads");
        replay_args.push_back(*threads);
    }
    const int code = replay_command(replay_args);
    if (code == kExitOk) std::cout << "frames written to " << fs::absolute(out_dir).string() << std::endl;
    return code;
}

}  // namespace

int play_command(const std::vector<std::string>& argv) {
    Args args(argv, {"--level", "--record", "--threads", "--quality", "--settings", "--ghost"}, {"--fullscreen", "--windowed"});
    if (!args.positional().empty()) throw UsageError("play takes no positional arguments");
    if (args.flag("--fullscreen") && args.flag("--windowed")) throw UsageError("--fullscreen or --windowed, not both");
    const int threads = args.integer("--threads", 1, 1, 64);
    quality_option(args);  // a bad --quality is a usage error here too
    if (!display_available()) return render_demo_headless(args);

    PlayOptions options;
    // The ghost's replay first: its level is the one played unless --level names another.
    if (auto ghost = args.value("--ghost")) {
        options.ghost = read_replay(*ghost, ReadOptions{});
        options.ghost_name = fs::path(*ghost).stem().string();
    }
    GameSession session =
        GameSession::open(args.value("--level").value_or(options.ghost ? options.ghost->header.level_id : "harbour"), threads);
    if (options.ghost)
        if (auto why = replay_mismatch(*options.ghost, *session.world, session.level.content_hash)) {
            std::cerr << "error: cannot race the ghost of " << *args.value("--ghost") << ": " << *why << "\n";
            return kExitBadInput;
        }
    if (auto record = args.value("--record")) options.record = fs::path(*record);
    options.player = player_settings(args);
    options.threads = threads;
    return play_in_window(session, options);
}

}  // namespace game
