// The replay viewer's window logic without a window (game/play/ReplayViewer.h,
// ViewerKeys.h, TimelineBar.h): which key does what, where ticks and markers sit on the
// timeline, and the viewer driven through the play loop on an offscreen screen by
// scripted keys: after seeks and steps the world is the recording's, tick for tick, and a
// take over records a file that checks from tick 0.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "game/capture/FrameCapture.h"
#include "game/cli/ExitCode.h"
#include "game/level/LevelLoader.h"
#include "game/play/ReplayViewer.h"
#include "game/play/TimelineBar.h"
#include "game/play/ViewerKeys.h"
#include "game/replay/ReplayReader.h"
#include "game/session/GameSession.h"

namespace fs = std::filesystem;
using game::ViewerAction;

namespace {

ViewerAction action(int key, bool shift = false) {
    const std::optional<game::ViewerKeyAction> a = game::viewer_action_for_key(key, shift);
    EXPECT_TRUE(a.has_value()) << "key " << key;
    return a ? a->action : ViewerAction::ToggleHud;
}

}  // namespace

TEST(ViewerKeys, EachKeyOfTheHelpDoesItsAction) {
    EXPECT_EQ(action(GLFW_KEY_SPACE), ViewerAction::TogglePause);
    EXPECT_EQ(action(GLFW_KEY_P), ViewerAction::TogglePause);
    EXPECT_EQ(action(GLFW_KEY_LEFT), ViewerAction::StepBack);
    EXPECT_EQ(action(GLFW_KEY_RIGHT), ViewerAction::StepForward);
    EXPECT_EQ(action(GLFW_KEY_LEFT, true), ViewerAction::JumpBack);
    EXPECT_EQ(action(GLFW_KEY_RIGHT, true), ViewerAction::JumpForward);
    for (int key : {GLFW_KEY_LEFT_BRACKET, GLFW_KEY_MINUS, GLFW_KEY_KP_SUBTRACT}) EXPECT_EQ(action(key), ViewerAction::Slower);
    for (int key : {GLFW_KEY_RIGHT_BRACKET, GLFW_KEY_EQUAL, GLFW_KEY_KP_ADD}) EXPECT_EQ(action(key), ViewerAction::Faster);
    for (int key : {GLFW_KEY_COMMA, GLFW_KEY_PAGE_UP}) EXPECT_EQ(action(key), ViewerAction::PreviousMarker);
    for (int key : {GLFW_KEY_PERIOD, GLFW_KEY_PAGE_DOWN}) EXPECT_EQ(action(key), ViewerAction::NextMarker);
    EXPECT_EQ(action(GLFW_KEY_HOME), ViewerAction::Start);
    EXPECT_EQ(action(GLFW_KEY_END), ViewerAction::End);
    EXPECT_EQ(action(GLFW_KEY_C), ViewerAction::NextCamera);
    EXPECT_EQ(action(GLFW_KEY_H), ViewerAction::ToggleHud);
    EXPECT_EQ(action(GLFW_KEY_T), ViewerAction::TakeOver);
    const game::ViewerCameraMode modes[] = {game::ViewerCameraMode::Recorded, game::ViewerCameraMode::Chase,
                                            game::ViewerCameraMode::Driver, game::ViewerCameraMode::FreeFly,
                                            game::ViewerCameraMode::Orbit};
    for (int i = 0; i < game::kViewerCameraModes; ++i) {
        const auto a = game::viewer_action_for_key(GLFW_KEY_1 + i, false);
        ASSERT_TRUE(a);
        EXPECT_EQ(a->action, ViewerAction::Camera);
        EXPECT_EQ(a->camera, modes[i]);
    }
}

TEST(ViewerKeys, TheFreeCameraAndProgramKeysAreNotTheViewers) {
    // W/A/S/D/Q/E fly the free camera (held, not pressed); Esc, F1, F12, M are the loop's.
    for (int key : {GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E, GLFW_KEY_ESCAPE, GLFW_KEY_F1,
                    GLFW_KEY_F12, GLFW_KEY_M, GLFW_KEY_6})
        EXPECT_FALSE(game::viewer_action_for_key(key, false)) << "key " << key;
}

TEST(TimelineBar, TicksAndPixelsMapBothWays) {
    const game::TimelineGeometry bar(100.0f, 1100.0f, 1716);
    EXPECT_FLOAT_EQ(bar.x_of(0), 100.0f);
    EXPECT_FLOAT_EQ(bar.x_of(1716), 1100.0f);
    EXPECT_FLOAT_EQ(bar.x_of(858), 600.0f);
    EXPECT_FLOAT_EQ(bar.x_of(5000), 1100.0f) << "past the end: at the end";
    EXPECT_EQ(bar.tick_at(100.0f), 0u);
    EXPECT_EQ(bar.tick_at(1100.0f), 1716u);
    EXPECT_EQ(bar.tick_at(0.0f), 0u) << "left of the bar: its start";
    EXPECT_EQ(bar.tick_at(5000.0f), 1716u);
    // Wider than the replay is long: every tick's pixel leads back to it.
    const game::TimelineGeometry wide(0.0f, 2000.0f, 1716);
    for (uint64_t t = 0; t <= 1716; ++t) ASSERT_EQ(wide.tick_at(wide.x_of(t)), t);
    // A marker at tick 1631 of 1716 on a 1000-pixel bar.
    EXPECT_NEAR(bar.x_of(1631), 100.0f + 1000.0f * 1631.0f / 1716.0f, 1e-3f);
    const game::TimelineGeometry empty(10.0f, 500.0f, 0);
    EXPECT_FLOAT_EQ(empty.x_of(0), 10.0f);
    EXPECT_EQ(empty.tick_at(300.0f), 0u);
}

TEST(TimelineBar, ClockReadsMinutesAndSeconds) {
    EXPECT_EQ(game::replay_clock(0), "0:00.00");
    EXPECT_EQ(game::replay_clock(1716), "0:28.60");
    EXPECT_EQ(game::replay_clock(60 * 75 + 30), "1:15.50");
}

namespace {

// The play loop's screen for the test: an offscreen target, a script of key presses (one
// entry a frame, with the keys held meanwhile), closed when the script ends.
class ScriptedScreen final : public game::Screen {
public:
    struct Frame {
        std::vector<int> presses;
        std::vector<int> held;
    };

    ScriptedScreen(int width, int height, std::vector<Frame> script)
        : size_{width, height}, target_(width, height), script_(std::move(script)) {}

    Size size() const override { return size_; }
    GLuint framebuffer() const override { return target_.output().framebuffer; }
    void handle_events(double) override {}
    void present() override { glFinish(); }
    bool should_close() const override { return close_; }
    void request_close() override { close_ = true; }
    std::vector<int> take_key_presses() override {
        if (next_ >= script_.size()) {
            close_ = true;  // after this frame, its keys held as in the last
            return {};
        }
        held_ = script_[next_].held;
        activity_ = !script_[next_].presses.empty();
        return script_[next_++].presses;
    }
    // A key press wakes an idle loop, as a window's events do.
    bool take_activity() override { return std::exchange(activity_, false); }
    bool key_down(int key) const override { return std::find(held_.begin(), held_.end(), key) != held_.end(); }

private:
    Size size_;
    game::FrameCapture target_;
    std::vector<Frame> script_;
    size_t next_ = 0;
    std::vector<int> held_;
    bool close_ = false;
    bool activity_ = false;
};

class ReplayViewerLoop : public HeadlessTest {
protected:
    game::Replay replay = game::read_replay(std::string(SPINDRIFT_TEST_DATA) + "/../../replays/harbour_goals.replay",
                                            game::ReadOptions{true});
    game::GameSession session = game::GameSession::open("harbour", 1, replay.header.seed);

    int watch(std::vector<ScriptedScreen::Frame> script, const game::ViewerOptions& options = {}) {
        ScriptedScreen screen(160, 90, std::move(script));
        return game::watch_replay(replay, session, screen,
                                  game::LoopOptions{.quality = game::QualityChoice::Low,
                                                    .cameras = game::CameraTrack(replay.header.camera_shots,
                                                                                 replay.header.tick_rate_hz)},
                                  options);
    }
    bool on_recording() const {
        const uint64_t t = session.world->tick();
        return t == 0 || session.world->hash().world == replay.tick_world_hashes[t - 1];
    }
};

}  // namespace

TEST_F(ReplayViewerLoop, SeeksAndStepsLandOnTheRecordedHashes) {
    const uint64_t end = replay.inputs.size();
    const int code = watch({
        {},                                // the first frame: nothing plays
        {}, {},                            // playing, through the loop's TickDriver
        {{GLFW_KEY_END}},                  // to the end
        {{GLFW_KEY_LEFT, GLFW_KEY_LEFT}},  // two ticks back
        {{GLFW_KEY_LEFT}, {GLFW_KEY_LEFT_SHIFT}},  // five seconds back
        {{GLFW_KEY_RIGHT}},                // a tick on
        {{GLFW_KEY_4, GLFW_KEY_H}, {GLFW_KEY_W}},  // free fly, HUD hidden: presentation only
    });
    EXPECT_EQ(code, game::kExitOk) << "no desync in the ticks played";
    EXPECT_EQ(session.world->tick(), end - 2 - 300 + 1);
    EXPECT_TRUE(on_recording()) << "the world at tick " << session.world->tick() << " is the recording's";
}

TEST_F(ReplayViewerLoop, ATakeOverRecordsAFileThatChecks) {
    const fs::path out = fs::temp_directory_path() / ("spindrift_viewer_take_over_" + std::to_string(::getpid()) + ".replay");
    std::vector<ScriptedScreen::Frame> script = {
        {},
        {{GLFW_KEY_HOME}},
        {{GLFW_KEY_RIGHT, GLFW_KEY_RIGHT}, {GLFW_KEY_LEFT_SHIFT}},  // ten seconds in
        {{GLFW_KEY_T}, {GLFW_KEY_W, GLFW_KEY_D}},
    };
    for (int f = 0; f < 20; ++f) script.push_back({{}, {GLFW_KEY_W, GLFW_KEY_D}});  // drive on
    EXPECT_EQ(watch(std::move(script), game::ViewerOptions{.record = out}), game::kExitOk);

    const game::Replay taken = game::read_replay(out, game::ReadOptions{true});
    ASSERT_GT(taken.inputs.size(), 600u) << "the old 600 ticks and some played";
    EXPECT_EQ(taken.inputs.size(), session.world->tick());
    for (size_t t = 0; t < 600; ++t) ASSERT_EQ(taken.inputs[t], replay.inputs[t]) << "tick " << t;
    for (size_t t = 600; t < taken.inputs.size(); ++t)
        EXPECT_TRUE(taken.inputs[t].has(sim::Control::Throttle)) << "tick " << t << " driven";
    const std::string check = std::string(SPINDRIFT_BIN) + " replay " + out.string() +
                              " --headless --check --frames none > /dev/null 2>&1";
    EXPECT_EQ(std::system(check.c_str()), 0) << check;
    fs::remove(out);
}
