#pragma once
#include <filesystem>

namespace game {

// Root holding levels/ and replays/: $SPINDRIFT_DATA if set; else, for an installed
// program (PREFIX/bin/spindrift), PREFIX/share/spindrift beside it; else the source
// tree the binary was built from.
std::filesystem::path data_dir();

// Where an installed program under `executable` finds its data: ../share/spindrift
// from its folder, if that holds levels/.
std::filesystem::path installed_data_dir(const std::filesystem::path& executable);

}  // namespace game
