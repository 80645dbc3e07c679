#pragma once
#include <filesystem>

namespace game {

// Root holding levels/ and replays/: $SPINDRIFT_DATA if set, else the source tree the
// binary was built from.
std::filesystem::path data_dir();

}  // namespace game
