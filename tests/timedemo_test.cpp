// The timedemo's numbers from its frame records (game/play/Timedemo's summarise), and
// its JSON; the command itself is run in cli_test.cpp.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "game/bench/TrivialFill.h"
#include "game/play/Timedemo.h"

namespace {

game::FrameRecord frame(double ms, float scale, int ticks) {
    game::FrameRecord f;
    f.frame_ms = ms;
    f.render_scale = scale;
    f.ticks = ticks;
    return f;
}

}  // namespace

TEST(Timedemo, TheFillIsTheMedianOfTheSamplesFromBothEndsOfTheRun) {
    // Two levels, as the fill reads on llvmpipe: the median follows the more common one.
    EXPECT_DOUBLE_EQ(game::median_ms({1.4, 0.7, 0.7, 1.3, 0.7}), 0.7);
    EXPECT_DOUBLE_EQ(game::median_ms({1.4, 0.7, 1.3, 0.7}), 1.3);
    EXPECT_DOUBLE_EQ(game::median_ms({}), 0.0);
}

TEST(Timedemo, PercentilesAreNearestRankOverTheFrames) {
    game::TimedemoRun run;
    for (int i = 1; i <= 100; ++i) run.frames.push_back(frame(double(i), 1.0f, 1));
    const game::TimedemoSummary s = game::summarise(run);
    EXPECT_EQ(s.frames, 100u);
    EXPECT_DOUBLE_EQ(s.frame_ms.p50, 50.0);
    EXPECT_DOUBLE_EQ(s.frame_ms.p95, 95.0);
    EXPECT_DOUBLE_EQ(s.frame_ms.p99, 99.0);
    EXPECT_DOUBLE_EQ(s.frame_ms.worst, 100.0);
    EXPECT_DOUBLE_EQ(s.frame_ms.mean, 50.5);
    EXPECT_DOUBLE_EQ(s.wall_s, 5.05);
    EXPECT_NEAR(s.average_fps, 100 / 5.05, 1e-9);
    EXPECT_NEAR(s.game_s, 100.0 / 60.0, 1e-9);
}

TEST(Timedemo, ScaleOverTimeAndGameOverWall) {
    game::TimedemoRun run;
    // 1.5 s at 0.75 with 3 ticks a 50 ms frame (real time), then 2 s at 0.5 falling
    // behind (2 ticks a 50 ms frame).
    for (int i = 0; i < 30; ++i) run.frames.push_back(frame(50.0, 0.75f, 3));
    for (int i = 0; i < 40; ++i) run.frames.push_back(frame(50.0, 0.5f, 2));
    const game::TimedemoSummary s = game::summarise(run);
    EXPECT_EQ(s.scale_each_second, (std::vector<float>{0.75f, 0.5f, 0.5f}));
    ASSERT_EQ(s.seconds_at_scale.size(), 2u);
    EXPECT_FLOAT_EQ(s.seconds_at_scale[0].first, 0.5f);
    EXPECT_NEAR(s.seconds_at_scale[0].second, 2.0, 1e-9);
    EXPECT_FLOAT_EQ(s.seconds_at_scale[1].first, 0.75f);
    EXPECT_NEAR(s.seconds_at_scale[1].second, 1.5, 1e-9);
    EXPECT_NEAR(s.game_s / s.wall_s, (170.0 / 60.0) / 3.5, 1e-9);
}

TEST(Timedemo, NoFramesIsZerosNotACrash) {
    const game::TimedemoSummary s = game::summarise(game::TimedemoRun{});
    EXPECT_EQ(s.frames, 0u);
    EXPECT_EQ(s.average_fps, 0.0);
    EXPECT_EQ(s.frame_ms.worst, 0.0);
    EXPECT_TRUE(s.scale_each_second.empty());
}

TEST(Timedemo, JsonGivesEveryTimeAlsoInFills) {
    game::TimedemoRun run;
    run.replay = "r.replay";
    run.width = 320;
    run.height = 180;
    run.fill_ms = 0.5;
    run.pass_ms = {{"water", 2.0}};
    run.desync = "tick 5";
    for (int i = 0; i < 10; ++i) run.frames.push_back(frame(10.0, 0.5f, 1));
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("spindrift_timedemo_" + std::to_string(::getpid()) + ".json");
    game::write_timedemo_json(path, run, game::summarise(run));
    std::ifstream in(path);
    const nlohmann::json j = nlohmann::json::parse(in);
    std::filesystem::remove(path);
    EXPECT_EQ(j["replay"], "r.replay");
    EXPECT_EQ(j["quality"], "auto");
    EXPECT_DOUBLE_EQ(j["frame_fills"]["p95"].get<double>(), 20.0);
    EXPECT_DOUBLE_EQ(j["passes"][0]["fills"].get<double>(), 4.0);
    EXPECT_EQ(j["desync"], "tick 5");
    EXPECT_EQ(j["seconds_at_scale"][0]["scale"], 0.5);
}
