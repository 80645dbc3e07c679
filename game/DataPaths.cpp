#include "game/DataPaths.h"

#include <cstdlib>

namespace game {

std::filesystem::path data_dir() {
    if (const char* env = std::getenv("SPINDRIFT_DATA"); env && *env) return env;
    return SPINDRIFT_DATA_DIR;
}

}  // namespace game
