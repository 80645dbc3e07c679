#include "game/session/GameSession.h"

#include <stdexcept>

namespace game {

GameSession GameSession::start(LoadedLevel level, int threads, std::optional<uint64_t> seed) {
    GameSession s;
    s.level = std::move(level);
    sim::LevelDesc desc = s.level.sim;
    if (seed) desc.seed = *seed;
    try {
        s.world = std::make_unique<sim::World>(std::move(desc), sim::WorldOptions{threads});
    } catch (const std::invalid_argument& e) {
        // The sim refuses parameters it cannot run (an unstable wave grid, say): that
        // is the level's fault, reported against its file.
        throw LevelError(s.level.path.string() + ": " + e.what());
    }
    return s;
}

}  // namespace game
