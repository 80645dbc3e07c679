// Input scripts: expansion of hold/tap lines to per-tick input, and every error with its line.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include "game/replay/InputScript.h"

namespace {

namespace fs = std::filesystem;
using sim::Control;

uint16_t bits(std::initializer_list<Control> controls) {
    uint16_t mask = 0;
    for (Control c : controls) mask = uint16_t(mask | uint16_t(c));
    return mask;
}

constexpr const char* kHarbourDrive = R"(# drive along the harbour
level harbour
frames 640x360
checkpoints 90 300 600

0    hold throttle
120  hold throttle steer_left       # from tick 120 hold these controls
200  tap camera                     # one tick only, on top of the held set
300  hold                           # hold nothing
900  end
)";

TEST(InputScript, ExpandsHoldsAndTapsAtTheirTicks) {
    const game::InputScript s = game::parse_script(kHarbourDrive, "drive.script");
    EXPECT_EQ(s.level, "harbour");
    EXPECT_EQ(s.frame_width, 640u);
    EXPECT_EQ(s.frame_height, 360u);
    EXPECT_EQ(s.checkpoints, (std::vector<uint32_t>{90, 300, 600}));
    EXPECT_EQ(s.end_tick, 900u);
    ASSERT_EQ(s.inputs.size(), 900u);
    const uint16_t throttle = bits({Control::Throttle});
    const uint16_t turning = bits({Control::Throttle, Control::SteerLeft});
    for (uint32_t t = 0; t < 900; ++t) {
        uint16_t expected = 0;
        if (t < 120) expected = throttle;
        else if (t < 300) expected = turning;
        if (t == 200) expected = uint16_t(turning | uint16_t(Control::Camera));
        ASSERT_EQ(s.inputs[t].held, expected) << "tick " << t;
    }
}

TEST(InputScript, TapsAddToTheHoldOfTheirTickWhateverTheLineOrder) {
    const game::InputScript s = game::parse_script(
        "5 tap fire\n5 tap fire camera\n5 hold brake\n6 tap wipers rain_up\n8 end", "taps.script");
    EXPECT_TRUE(s.level.empty());
    EXPECT_EQ(s.frame_width, 480u);
    EXPECT_EQ(s.frame_height, 270u);
    EXPECT_TRUE(s.checkpoints.empty());
    ASSERT_EQ(s.inputs.size(), 8u);
    for (uint32_t t = 0; t < 5; ++t) EXPECT_EQ(s.inputs[t].held, 0) << t;
    EXPECT_EQ(s.inputs[5].held, bits({Control::Brake, Control::Fire, Control::Camera}));
    EXPECT_EQ(s.inputs[6].held, bits({Control::Brake, Control::Wipers, Control::RainUp}));
    EXPECT_EQ(s.inputs[7].held, bits({Control::Brake}));
}

TEST(InputScript, AnalogAxesHoldLikeControlsAndTapsReplaceThemForOneTick) {
    const game::InputScript s = game::parse_script(
        "0 hold throttle=0.5 steer=-0.25\n"
        "3 tap steer=1 fire\n"
        "4 hold brake=1 steer_left\n"
        "6 hold\n"
        "7 end",
        "analog.script");
    ASSERT_EQ(s.inputs.size(), 7u);
    EXPECT_EQ(s.inputs[0], (sim::TickInput{0, 128, 0, -32}));  // round(0.5 * 255), round(-0.25 * 127)
    EXPECT_EQ(s.inputs[2], s.inputs[0]);
    EXPECT_EQ(s.inputs[3], (sim::TickInput{bits({Control::Fire}), 128, 0, 127}));
    EXPECT_EQ(s.inputs[4], (sim::TickInput{bits({Control::SteerLeft}), 0, 255, 0}));  // a hold replaces the axes too
    EXPECT_EQ(s.inputs[6], sim::TickInput{});
    // A script without axes has none: the bundled scripts mean what they meant.
    for (const sim::TickInput& in : game::parse_script(kHarbourDrive, "drive.script").inputs) {
        ASSERT_EQ(in.throttle, 0);
        ASSERT_EQ(in.brake, 0);
        ASSERT_EQ(in.steer, 0);
    }
}

TEST(InputScript, AcceptsCommentsBlankLinesAndCrlf) {
    const game::InputScript s =
        game::parse_script("\r\n  # only a comment\r\n\t0 hold brake   # trailing\r\n\r\n3 end\r\n\r\n", "crlf.script");
    ASSERT_EQ(s.inputs.size(), 3u);
    EXPECT_EQ(s.inputs[2].held, bits({Control::Brake}));
}

// parse_script must throw "bad.script:LINE: ..." holding every one of `words`.
void expect_script_error(const std::string& text, int line, std::initializer_list<std::string> words) {
    SCOPED_TRACE(text);
    try {
        game::parse_script(text, "bad.script");
        ADD_FAILURE() << "no ScriptError thrown";
    } catch (const game::ScriptError& e) {
        const std::string message = e.what();
        const std::string where = "bad.script:" + std::to_string(line) + ": ";
        EXPECT_EQ(message.rfind(where, 0), 0u) << message << "\ndoes not start with " << where;
        for (const std::string& w : words) EXPECT_NE(message.find(w), std::string::npos) << message << "\nlacks: " << w;
    }
}

TEST(InputScript, NamesTheLineOfEachError) {
    expect_script_error("0 hold\nspeed 3\n10 end", 2, {"unknown directive 'speed'"});
    expect_script_error("0 hold throttle nitro\n10 end", 1,
                        {"unknown control 'nitro'", "throttle", "steer_left", "rain_down"});
    expect_script_error("0 hold\n120 hold throttle\n100 hold\n900 end", 3,
                        {"tick 100 is before the previous tick 120: ticks must not go back"});
    expect_script_error("0 hold\n120 hold\n100 end", 3, {"tick 100 is before the previous tick 120"});
    expect_script_error("12a hold\n20 end", 1, {"'12a' is not a tick number"});
    expect_script_error("0 hold\n-5 hold\n20 end", 2, {"tick -5 is negative"});
    expect_script_error("864001 end", 1, {"tick 864001 is above the limit 864000"});
    expect_script_error("0 hold\n99999999999999999999999 end", 2, {"above the limit 864000"});
    expect_script_error("0 hold\n10 press throttle\n20 end", 2, {"unknown action 'press'", "hold, tap, camera or end"});
    expect_script_error("0 hold\n10\n20 end", 2, {"tick 10 needs an action"});
    expect_script_error("10 tap\n20 end", 1, {"'tap' needs at least one control"});
    expect_script_error("0 hold\n5 hold brake\n", 2, {"no 'end' line"});
    expect_script_error("", 1, {"no 'end' line"});
    expect_script_error("0 hold\n20 end\n30 hold brake\n", 3, {"'end' must be the last line", "line 2"});
    expect_script_error("20 end\nlevel harbour\n", 2, {"'end' must be the last line"});
    expect_script_error("20 end throttle", 1, {"'end' takes no controls"});
    expect_script_error("0 end", 1, {"at least 1"});
    expect_script_error("0 hold\n20 hold brake\n20 end", 3, {"ends at tick 20", "never be applied"});
    expect_script_error("0 hold\n5 hold brake\n5 hold fire\n20 end", 3, {"tick 5 already has a 'hold' on line 2"});
    expect_script_error("0 hold throttle=1.5\n20 end", 1, {"'throttle=1.5'", "a number in 0..1"});
    expect_script_error("0 hold brake=-0.1\n20 end", 1, {"a number in 0..1"});
    expect_script_error("0 hold steer=-1.01\n20 end", 1, {"'steer=-1.01'", "a number in -1..1"});
    expect_script_error("0 hold steer=half\n20 end", 1, {"'steer=half'"});
    expect_script_error("0 hold steer=\n20 end", 1, {"'steer='"});
    expect_script_error("0 hold steer=0.5x\n20 end", 1, {"'steer=0.5x'"});
    expect_script_error("0 hold steer=nan\n20 end", 1, {"'steer=nan'"});
    expect_script_error("0 hold nitro=1\n20 end", 1, {"unknown axis 'nitro'", "steer=-1..1"});
    expect_script_error("0 hold steer=0.1 steer=0.2\n20 end", 1, {"axis 'steer' is set twice"});
}

TEST(InputScript, ChecksCheckpointsFramesAndDuplicates) {
    expect_script_error("checkpoints 10 900\n0 hold\n900 end", 3, {"checkpoint 900 (line 1)", "not before the end tick 900"});
    expect_script_error("checkpoints 10 50 30\n100 end", 1, {"ascending and unique", "30 follows 50"});
    expect_script_error("checkpoints 10 10\n100 end", 1, {"ascending and unique"});
    expect_script_error("checkpoints\n100 end", 1, {"at least one tick"});
    expect_script_error("checkpoints 10 x\n100 end", 1, {"'x' is not a checkpoint number"});
    for (const char* bad : {"frames 480", "frames 480x", "frames x270", "frames 8x270", "frames 480x5000",
                            "frames 480x270x2", "frames 480 270", "frames -480x270", "frames 99999999x270"}) {
        expect_script_error(std::string("# size\n") + bad + "\n100 end", 2, {"'frames' takes WIDTHxHEIGHT", "16..4096"});
    }
    expect_script_error("level harbour\nlevel docks\n100 end", 2, {"duplicate 'level' line", "line 1"});
    expect_script_error("frames 64x64\n\nframes 64x64\n100 end", 3, {"duplicate 'frames' line", "line 1"});
    expect_script_error("checkpoints 1\ncheckpoints 2\n100 end", 2, {"duplicate 'checkpoints' line"});
    expect_script_error("level\n100 end", 1, {"'level' takes exactly one level name"});
    expect_script_error("level ../etc\n100 end", 1, {"level name '../etc'"});
    // Limits that are fine.
    const game::InputScript s = game::parse_script("frames 16x4096\ncheckpoints 0 863999\n864000 end", "max.script");
    EXPECT_EQ(s.inputs.size(), 864000u);
    EXPECT_EQ(s.frame_height, 4096u);
}

TEST(InputScript, CameraLinesPlaceTheCameraFromTheirTickAndLeaveTheInputAlone) {
    const game::InputScript s = game::parse_script(
        "0 hold throttle\n"
        "100 camera look 10 3 -20  0 1.5 -30 fov=40\n"
        "100 hold brake\n"
        "200 camera orbit 0 1 -30  8 3 -20 from=90\n"
        "300 camera follow\n"
        "400 end\n",
        "cameras.script");
    ASSERT_EQ(s.camera_shots.size(), 3u);
    game::CameraShot look;
    look.tick = 100;
    look.kind = game::CameraShotKind::Look;
    look.point = {10.0f, 3.0f, -20.0f};
    look.target = {0.0f, 1.5f, -30.0f};
    look.fov_deg = 40.0f;
    EXPECT_EQ(s.camera_shots[0], look);
    game::CameraShot orbit;
    orbit.tick = 200;
    orbit.kind = game::CameraShotKind::Orbit;
    orbit.point = {0.0f, 1.0f, -30.0f};
    orbit.radius_m = 8.0f;
    orbit.height_m = 3.0f;
    orbit.deg_per_s = -20.0f;
    orbit.start_deg = 90.0f;
    EXPECT_EQ(s.camera_shots[1], orbit);
    EXPECT_EQ(s.camera_shots[2].kind, game::CameraShotKind::Follow);
    EXPECT_EQ(s.camera_shots[2].tick, 300u);
    // The camera is not input: the held controls are what the hold lines say.
    ASSERT_EQ(s.inputs.size(), 400u);
    EXPECT_EQ(s.inputs[99].held, bits({Control::Throttle}));
    EXPECT_EQ(s.inputs[100].held, bits({Control::Brake}));
    EXPECT_EQ(s.inputs[399].held, bits({Control::Brake}));
}

TEST(InputScript, NamesTheLineOfEachCameraError) {
    expect_script_error("10 camera\n20 end", 1, {"a camera line is", "camera look", "camera orbit", "camera follow"});
    expect_script_error("10 camera pan 1 2 3\n20 end", 1, {"a camera line is"});
    expect_script_error("10 camera look 1 2 3 4 5\n20 end", 1, {"'camera look' needs 6 numbers"});
    expect_script_error("10 camera look 1 2 3 4 5 x\n20 end", 1, {"'x' is not a number", "target z"});
    expect_script_error("10 camera look 1 2 3 1 2 3\n20 end", 1, {"eye and target are the same point"});
    expect_script_error("10 camera look 1 2 3 1 9 3\n20 end", 1, {"straight up or down"});
    expect_script_error("10 camera look 1 2 3 4 5 6 fov=200\n20 end", 1, {"field of view", "5..120"});
    expect_script_error("10 camera look 1 2 3 4 5 6 fov=40 fov=50\n20 end", 1, {"unexpected 'fov=50'"});
    expect_script_error("10 camera look 1 2 3 4 5 6 from=40\n20 end", 1, {"unexpected 'from=40'"});
    expect_script_error("10 camera look 1 2 3 4 5 6 fov=\n20 end", 1, {"'' is not a number", "field of view"});
    expect_script_error("10 camera look 1 2 3 4 5 999999\n20 end", 1, {"100 km"});
    expect_script_error("10 camera orbit 0 0 0 0 2 10\n20 end", 1, {"orbit radius", "0.1..10000"});
    expect_script_error("10 camera orbit 0 0 0 5 2 9000\n20 end", 1, {"faster than 3600"});
    expect_script_error("10 camera orbit 0 0 0 5 2 10 from=400\n20 end", 1, {"start angle"});
    expect_script_error("10 camera orbit 0 0 0 0.1 50 10\n20 end", 1, {"straight up or down"});
    expect_script_error("10 camera follow now\n20 end", 1, {"unexpected 'now'"});
    expect_script_error("10 camera follow\n10 camera look 1 2 3 4 5 6\n20 end", 2, {"already has a camera line"});
    expect_script_error("10 camera follow\n5 hold\n20 end", 2, {"tick 5 is before the previous tick 10"});
    expect_script_error("0 hold\n20 camera follow\n20 end", 3, {"ends at tick 20"});
}

class InputScriptFile : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("spindrift_script_test_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(InputScriptFile, LoadsFromDiskAndRefusesBadFiles) {
    const fs::path path = dir_ / "drive.script";
    std::ofstream(path) << kHarbourDrive;
    const game::InputScript s = game::load_script(path);
    EXPECT_EQ(s.end_tick, 900u);
    EXPECT_EQ(s.inputs[200].held, bits({Control::Throttle, Control::SteerLeft, Control::Camera}));

    std::ofstream(dir_ / "broken.script") << "0 hold\n5 hold warp\n10 end\n";
    try {
        game::load_script(dir_ / "broken.script");
        ADD_FAILURE() << "no ScriptError";
    } catch (const game::ScriptError& e) {
        EXPECT_NE(std::string(e.what()).find((dir_ / "broken.script").string() + ":2: unknown control 'warp'"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(game::load_script(dir_ / "missing.script"), game::ScriptError);
    try {
        game::load_script(dir_ / "missing.script");
    } catch (const game::ScriptError& e) {
        EXPECT_NE(std::string(e.what()).find("missing.script"), std::string::npos) << e.what();
    }
    EXPECT_THROW(game::load_script(dir_), game::ScriptError);
    {
        std::ofstream big(dir_ / "big.script");
        big << std::string((1u << 20) + 1, '#');
    }
    try {
        game::load_script(dir_ / "big.script");
        ADD_FAILURE() << "no ScriptError";
    } catch (const game::ScriptError& e) {
        EXPECT_NE(std::string(e.what()).find("1 MiB"), std::string::npos) << e.what();
    }
}

}  // namespace
