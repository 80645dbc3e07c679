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
    // Loads the level with its fibre image (inline: the GL-free checker, which cannot
    // read images, uses start(load_level(name, nullptr), ...) instead).
    static GameSession open(std::string_view level_name_or_path, int threads, std::optional<uint64_t> seed = {}) {
        return start(load_level(level_name_or_path), threads, seed);
    }
    // The world of a level already loaded; a level the sim refuses is a LevelError.
    static GameSession start(LoadedLevel level, int threads, std::optional<uint64_t> seed = {});
};

}  // namespace game
