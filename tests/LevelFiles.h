#pragma once
// The level loader tests' files: the harbour level, temporary level files, and the
// check that an edited level is refused with a message naming the file and the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "game/DataPaths.h"
#include "game/level/LevelError.h"
#include "game/level/LevelLoader.h"

namespace level_files {

namespace fs = std::filesystem;
using nlohmann::json;

inline fs::path test_levels() { return fs::path(SPINDRIFT_TEST_DATA) / "levels"; }
inline fs::path harbour_json() { return game::data_dir() / "levels" / "harbour.json"; }
inline fs::path harbour_asset(const char* name) { return game::data_dir() / "levels" / "harbour" / name; }

// A fresh directory under the system temp dir, removed afterwards.
struct TempDir {
    fs::path path;
    explicit TempDir(const std::string& tag) {
        path = fs::temp_directory_path() / ("spindrift_level_test_" + tag + "_" + std::to_string(::getpid()));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

inline std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
inline void spit(const fs::path& p, const std::string& bytes) {
    std::ofstream out(p, std::ios::binary);
    out << bytes;
}

// Runs `load` and expects a LevelError whose message contains every one of `words`.
inline void expect_error(const std::function<void()>& load, const std::vector<std::string>& words) {
    try {
        load();
        ADD_FAILURE() << "no LevelError; expected one mentioning '" << words.front() << "'";
    } catch (const game::LevelError& e) {
        std::string msg = e.what();
        for (const std::string& w : words) EXPECT_NE(msg.find(w), std::string::npos) << "'" << w << "' not in: " << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line expected: " << msg;
    }
}

// One thing changed in the harbour level, and the words its LevelError must contain.
struct LevelEdit {
    std::function<void(json&)> edit;
    std::vector<std::string> words;
};

// Each edit of the harbour level, written to a file of its own under `tag`, must fail to
// load with a message naming that file and containing the edit's words.
inline void expect_each_refused(const std::string& tag, const json& base, const std::vector<LevelEdit>& cases) {
    TempDir tmp(tag);
    for (size_t i = 0; i < cases.size(); ++i) {
        SCOPED_TRACE("case " + std::to_string(i));
        json j = base;
        cases[i].edit(j);
        fs::path file = tmp.path / ("case" + std::to_string(i) + ".json");
        spit(file, j.dump(1));
        std::vector<std::string> words = cases[i].words;
        words.push_back(file.string() + ": ");
        expect_error([&] { game::load_level(file.string()); }, words);
    }
}

}  // namespace level_files
