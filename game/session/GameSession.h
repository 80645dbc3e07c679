#pragma once
// A level loaded and its world made: what every command starts from.
#include <memory>
#include <optional>
#include <string_view>

#include "game/level/LevelLoader.h"
#include "sim/world/World.h"

namespace game {

struct GameSession {
    LoadedLevel level;
    std::unique_ptr<sim::World> world;

    // `seed` overrides the level's (a replay's header carries the seed it was made with).
    static GameSession open(std::string_view level_name_or_path, int threads, std::optional<uint64_t> seed = {});
    // The world of a level already loaded; a level the sim refuses is a LevelError.
    static GameSession start(LoadedLevel level, int threads, std::optional<uint64_t> seed = {});
};

}  // namespace game
