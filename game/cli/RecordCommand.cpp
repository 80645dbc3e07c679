// spindrift record --level NAME --script FILE --out FILE [--threads N]
#include <filesystem>
#include <iostream>

#include "game/cli/Args.h"
#include "game/cli/Commands.h"
#include "game/cli/ExitCode.h"
#include "game/cli/Progress.h"
#include "game/replay/InputScript.h"
#include "game/replay/ReplayWriter.h"
#include "game/session/GameSession.h"
#include "game/session/ReplayHeaderFor.h"

namespace game {

int record_command(const std::vector<std::string>& argv) {
    Args args(argv, {"--level", "--script", "--out", "--threads"}, {});
    if (!args.positional().empty()) throw UsageError("record takes no positional arguments");
    auto script_path = args.value("--script");
    auto out = args.value("--out");
    if (!script_path || !out) throw UsageError("record needs --script FILE and --out FILE");
    const int threads = args.integer("--threads", 1, 1, 64);

    // Everything is checked before the output file exists.
    InputScript script = load_script(*script_path);
    std::string level = args.value("--level").value_or(script.level);
    if (level.empty()) throw UsageError("record needs --level NAME (the script names none)");
    GameSession session = GameSession::open(level, threads);
    if (!script.level.empty() && script.level != session.level.sim.id) {
        std::cerr << "error: " << *script_path << " is written for level '" << script.level << "', not '"
                  << session.level.sim.id << "'\n";
        return kExitBadInput;
    }
    if (!script.checkpoints.empty() && script.checkpoints.front() == 0) {
        std::cerr << "error: " << *script_path << ": checkpoint 0 is before the first tick; checkpoints start at 1\n";
        return kExitBadInput;
    }
    ReplayHeader header = replay_header_for(session, script.frame_width, script.frame_height, script.checkpoints);
    header.camera_shots = script.camera_shots;

    ReplayWriter writer = ReplayWriter::create(*out, header);
    Progress progress("record " + std::filesystem::path(*out).filename().string(), script.inputs.size(), "ticks");
    try {
        for (const sim::TickInput& in : script.inputs) {
            sim::TickInput q = sim::quantise(in);
            session.world->step(q);
            writer.append(q, session.world->hash());
            progress.update(size_t(session.world->tick()));
        }
        writer.finish();
    } catch (...) {
        // A recording that failed is not left behind to be mistaken for a cut one.
        writer.discard();
        throw;
    }
    progress.finish();
    std::cout << "recorded " << writer.ticks() << " ticks of level '" << header.level_id << "' to " << *out << "\n";
    return kExitOk;
}

}  // namespace game
