#pragma once
// What the replay file tests and the replay checker tests share: a temporary directory
// per test, and a header that fills every field (camera shots included).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "game/replay/ReplayFormat.h"

namespace replay_test {

namespace fs = std::filesystem;

// A fresh directory under the system temp dir, removed afterwards.
class ReplayFile : public ::testing::Test {
protected:
    void SetUp() override {
        static int counter = 0;
        dir_ = fs::temp_directory_path() /
               ("spindrift_replay_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path file(const char* name) const { return dir_ / name; }

    fs::path dir_;
};

// A look, an orbit and a follow shot.
inline std::vector<game::CameraShot> test_camera_shots() {
    game::CameraShot look{.tick = 100, .kind = game::CameraShotKind::Look, .point = {10.0f, 3.0f, -20.0f},
                          .target = {0.0f, 1.5f, -30.0f}, .fov_deg = 40.0f};
    game::CameraShot orbit{.tick = 200, .kind = game::CameraShotKind::Orbit, .point = {0.0f, 1.0f, -30.0f},
                           .radius_m = 8.0f, .height_m = 3.0f, .deg_per_s = -20.0f, .start_deg = 90.0f};
    game::CameraShot follow{.tick = 300};
    return {look, orbit, follow};
}


inline game::ReplayHeader test_header(size_t subsystems = 3) {
    game::ReplayHeader h;
    h.level_id = "harbour";
    h.level_hash = 0x1122334455667788ull;
    h.seed = 42;
    h.tick_rate_hz = 60;
    h.sim_signature = 0xDEADBEEFCAFEF00Dull;
    h.frame_width = 320;
    h.frame_height = 180;
    h.checkpoints = {90, 300, 600};
    h.camera_shots = test_camera_shots();
    const char* names[] = {"vehicles", "water", "rain", "fluid", "dust"};
    for (size_t i = 0; i < subsystems; ++i) h.subsystem_names.push_back(names[i]);
    h.sim_params = R"({"gravity_mps2": 9.81})";
    return h;
}

}  // namespace replay_test
