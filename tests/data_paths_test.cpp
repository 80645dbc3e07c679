// Where the program finds levels/ and replays/: installed, beside it under share/.
#include "game/DataPaths.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

namespace fs = std::filesystem;

TEST(DataPaths, AnInstalledProgramFindsShareSpindriftBesideIt) {
    const fs::path prefix = fs::temp_directory_path() / ("spindrift_prefix_" + std::to_string(::getpid()));
    fs::remove_all(prefix);
    fs::create_directories(prefix / "bin");
    const fs::path program = prefix / "bin" / "spindrift";
    // No share/spindrift/levels yet: not an installed program.
    EXPECT_TRUE(game::installed_data_dir(program).empty());
    fs::create_directories(prefix / "share" / "spindrift");
    EXPECT_TRUE(game::installed_data_dir(program).empty());
    fs::create_directories(prefix / "share" / "spindrift" / "levels");
    EXPECT_EQ(game::installed_data_dir(program), prefix / "share" / "spindrift");
    fs::remove_all(prefix);
}

TEST(DataPaths, TheBuildTreesProgramUsesTheSourceTree) {
    // The test binary sits in the build tree, with no share/ beside it.
    EXPECT_TRUE(fs::exists(game::data_dir() / "levels" / "harbour.json")) << game::data_dir();
}
