#include "game/session/GameSession.h"

namespace game {

GameSession GameSession::open(std::string_view level_name_or_path, int threads, std::optional<uint64_t> seed) {
    GameSession s;
    s.level = load_level(level_name_or_path);
    sim::LevelDesc desc = s.level.sim;
    if (seed) desc.seed = *seed;
    s.world = std::make_unique<sim::World>(std::move(desc), sim::WorldOptions{threads});
    return s;
}

}  // namespace game
