// Play mode without a window: key mapping, the fixed-step clock, HUD text, param
// grouping, quality names, screenshot names and the no-display fallback.
#include "game/cli/Commands.h"
#include "game/cli/ExitCode.h"
#include "game/play/DebugUi.h"
#include "game/play/FixedStepClock.h"
#include "game/play/KeyboardInput.h"
#include "game/play/PlayLoop.h"
#include "game/play/PlayMode.h"
#include "game/play/QualityChoice.h"
#include "game/settings/KeyNames.h"
#include "game/replay/FrameSelection.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using game::UiAction;
using sim::Control;

namespace {

sim::TickInput keys(std::set<int> down) {
    return game::input_from_keys(game::KeyBindings(), [&](int key) { return down.count(key) != 0; });
}

uint16_t bit(Control c) { return static_cast<uint16_t>(c); }

// Sets an environment variable for one scope and restores it afterwards.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value)
            setenv(name, value, 1);
        else
            unsetenv(name);
    }
    ~ScopedEnv() {
        if (old_)
            setenv(name_, old_->c_str(), 1);
        else
            unsetenv(name_);
    }

private:
    const char* name_;
    std::optional<std::string> old_;
};

}  // namespace

TEST(KeyboardInput, NoKeysNoControls) { EXPECT_EQ(keys({}).held, 0); }

TEST(KeyboardInput, EachKeyFromTheHelpHoldsItsControl) {
    const std::pair<int, Control> expected[] = {
        {GLFW_KEY_W, Control::Throttle},        {GLFW_KEY_UP, Control::Throttle},
        {GLFW_KEY_S, Control::Brake},           {GLFW_KEY_DOWN, Control::Brake},
        {GLFW_KEY_A, Control::SteerLeft},       {GLFW_KEY_LEFT, Control::SteerLeft},
        {GLFW_KEY_D, Control::SteerRight},      {GLFW_KEY_RIGHT, Control::SteerRight},
        {GLFW_KEY_E, Control::SwitchVehicle},   {GLFW_KEY_1, Control::ThrowHeavy},
        {GLFW_KEY_2, Control::ThrowLight},      {GLFW_KEY_SPACE, Control::Fire},
        {GLFW_KEY_C, Control::Camera},          {GLFW_KEY_V, Control::Wipers},
        {GLFW_KEY_R, Control::RainUp},          {GLFW_KEY_F, Control::RainDown},
    };
    for (auto [key, control] : expected) {
        EXPECT_EQ(keys({key}).held, bit(control)) << "GLFW key " << key;
        EXPECT_EQ(game::control_for_key(game::KeyBindings(), key), control) << "GLFW key " << key;
    }
}

TEST(KeyboardInput, EveryControlHasAKeyAndOnlyOneBinding) {
    uint16_t seen = 0;
    const game::KeyBindings bindings;
    for (const game::ActionInfo& a : game::actions()) {
        EXPECT_NE(bindings.keys(a.action)[0], 0) << a.id;
        EXPECT_NE(a.control.has_value(), a.ui.has_value()) << a.id;
        if (!a.control) continue;
        EXPECT_EQ(seen & bit(*a.control), 0) << "control bound twice";
        seen |= bit(*a.control);
    }
    EXPECT_EQ(seen, sim::kAllControls);
}

TEST(KeyboardInput, KeysCombine) {
    EXPECT_EQ(keys({GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_SPACE}).held,
              bit(Control::Throttle) | bit(Control::SteerLeft) | bit(Control::Fire));
    // Both steering keys stay set; the sim steers by their difference.
    EXPECT_EQ(keys({GLFW_KEY_LEFT, GLFW_KEY_D}).held, bit(Control::SteerLeft) | bit(Control::SteerRight));
    // W and Up together are still one throttle.
    EXPECT_EQ(keys({GLFW_KEY_W, GLFW_KEY_UP}).held, bit(Control::Throttle));
}

TEST(KeyboardInput, AllBoundKeysGiveAQuantisedInput) {
    std::set<int> all;
    const game::KeyBindings bindings;
    for (const game::ActionInfo& a : game::actions())
        if (a.control)
            for (int k : bindings.keys(a.action))
                if (k) all.insert(k);
    sim::TickInput in = keys(all);
    EXPECT_EQ(in.held, sim::kAllControls);
    EXPECT_EQ(sim::quantise(in), in);
}

TEST(KeyboardInput, ProgramKeysAreNotControls) {
    const game::KeyBindings bindings;
    for (int key : {GLFW_KEY_P, GLFW_KEY_M, GLFW_KEY_F12, GLFW_KEY_F1, GLFW_KEY_F2, GLFW_KEY_F3, GLFW_KEY_F11,
                    game::kKeyAltEnter, GLFW_KEY_ESCAPE}) {
        EXPECT_EQ(keys({key}).held, 0) << "GLFW key " << key;
        EXPECT_FALSE(game::control_for_key(bindings, key).has_value()) << "GLFW key " << key;
        EXPECT_TRUE(game::ui_action_for_key(bindings, key).has_value()) << "GLFW key " << key;
    }
    EXPECT_EQ(game::ui_action_for_key(bindings, GLFW_KEY_P), UiAction::Pause);
    EXPECT_EQ(game::ui_action_for_key(bindings, GLFW_KEY_M), UiAction::ToggleMute);
    EXPECT_EQ(game::ui_action_for_key(bindings, GLFW_KEY_F12), UiAction::Screenshot);
    EXPECT_EQ(game::ui_action_for_key(bindings, GLFW_KEY_F1), UiAction::ToggleDebugPanel);
    EXPECT_EQ(game::ui_action_for_key(bindings, GLFW_KEY_F2), UiAction::ToggleProfileTiming);
    EXPECT_EQ(game::ui_action_for_key(bindings, GLFW_KEY_F3), UiAction::ToggleAntialiasing);
    EXPECT_EQ(game::ui_action_for_key(bindings, GLFW_KEY_F11), UiAction::Fullscreen);
    EXPECT_EQ(game::ui_action_for_key(bindings, game::kKeyAltEnter), UiAction::Fullscreen);
    EXPECT_EQ(game::ui_action_for_key(bindings, GLFW_KEY_ESCAPE), UiAction::Menu);
    for (const game::ActionInfo& a : game::actions()) {
        if (!a.control) continue;
        for (int k : bindings.keys(a.action)) {
            if (k) {
                EXPECT_FALSE(game::ui_action_for_key(bindings, k).has_value()) << "GLFW key " << k;
            }
        }
    }
}

TEST(KeyboardInput, ARebindMovesTheControl) {
    game::KeyBindings bindings;
    ASSERT_TRUE(bindings.bind(game::Action::Fire, 0, GLFW_KEY_J).bound);
    EXPECT_EQ(game::control_for_key(bindings, GLFW_KEY_J), Control::Fire);
    EXPECT_FALSE(game::control_for_key(bindings, GLFW_KEY_SPACE).has_value());
    EXPECT_EQ(game::input_from_keys(bindings, [](int k) { return k == GLFW_KEY_J; }).held, bit(Control::Fire));
    EXPECT_EQ(game::input_from_keys(bindings, [](int k) { return k == GLFW_KEY_SPACE; }).held, 0);
}

TEST(KeyboardInput, MuteIsABindableAction) {
    game::KeyBindings bindings;
    ASSERT_TRUE(bindings.bind(game::Action::Mute, 0, GLFW_KEY_N).bound);
    EXPECT_EQ(game::ui_action_for_key(bindings, GLFW_KEY_N), UiAction::ToggleMute);
    EXPECT_FALSE(game::ui_action_for_key(bindings, GLFW_KEY_M).has_value());
    EXPECT_EQ(game::action_from_id("mute"), game::Action::Mute);
}

using std::chrono::milliseconds;
using std::chrono::nanoseconds;

// A frame of 1/hz seconds, rounded to whole nanoseconds as a real clock would.
nanoseconds frame_of(int hz) { return nanoseconds(1'000'000'000 / hz); }

TEST(FixedStepClock, OneTickPerTickOfTime) {
    game::FixedStepClock clock(60);
    int ticks = 0;
    // 1/60 s is not a whole number of nanoseconds: 16666667, 16666667, 16666666 add up.
    for (int i = 0; i < 600; ++i) ticks += clock.advance(frame_of(60) + nanoseconds(i % 3 < 2 ? 1 : 0));
    EXPECT_EQ(ticks, 600);
}

TEST(FixedStepClock, NoDriftOverAnHour) {
    game::FixedStepClock clock(60);
    int64_t ticks = 0;
    for (int i = 0; i < 3600; ++i)
        for (int j = 0; j < 20; ++j) ticks += clock.advance(milliseconds(50));
    EXPECT_EQ(ticks, 60 * 3600);
    EXPECT_EQ(clock.pending(), nanoseconds(0));
}

TEST(FixedStepClock, FastFramesAccumulate) {
    game::FixedStepClock clock(60);
    int ticks = 0, frames_without_tick = 0;
    for (int i = 0; i < 144 * 10; ++i) {
        int n = clock.advance(frame_of(144));
        ticks += n;
        frames_without_tick += n == 0;
        EXPECT_LE(n, 1);
    }
    EXPECT_NEAR(ticks, 600, 1);
    EXPECT_GT(frames_without_tick, 0);
}

TEST(FixedStepClock, SlowFramesAreCappedAndTheRestDropped) {
    game::FixedStepClock clock(60, 5);
    EXPECT_EQ(clock.advance(milliseconds(2000)), 5);
    EXPECT_LT(clock.pending(), frame_of(60));
    EXPECT_EQ(clock.advance(nanoseconds(0)), 0);
    // 4.5 ticks of time: 4 now, the half kept for the next frame.
    game::FixedStepClock c2(100, 5);
    EXPECT_EQ(c2.advance(milliseconds(45)), 4);
    EXPECT_EQ(c2.pending(), milliseconds(5));
    EXPECT_EQ(c2.advance(milliseconds(5)), 1);
    EXPECT_EQ(c2.pending(), nanoseconds(0));
    // Exactly the limit is not "behind": nothing is dropped.
    EXPECT_EQ(c2.advance(milliseconds(57)), 5);
    EXPECT_EQ(c2.pending(), milliseconds(7));
}

TEST(FixedStepClock, SlowFramesAreMadeUpInFull) {
    game::FixedStepClock clock(60);
    // 10 fps: six ticks a frame, so the world keeps real time.
    int ticks = 0;
    for (int i = 0; i < 50; ++i) {
        const int n = clock.advance(milliseconds(100));
        EXPECT_EQ(n, 6);
        EXPECT_EQ(clock.dropped(), nanoseconds(0));
        ticks += n;
    }
    EXPECT_EQ(ticks, 300);
    // Uneven frames of 70..230 ms add up to the real time they cover.
    game::FixedStepClock uneven(60);
    int64_t total_ms = 0;
    ticks = 0;
    for (int i = 0; i < 300; ++i) {
        const int ms = 70 + (i * 37) % 161;
        total_ms += ms;
        ticks += uneven.advance(milliseconds(ms));
        EXPECT_EQ(uneven.dropped(), nanoseconds(0)) << "frame " << i;
    }
    EXPECT_EQ(ticks, total_ms * 60 / 1000);
}

TEST(FixedStepClock, OnlyASpiralIsCapped) {
    game::FixedStepClock clock(60);
    EXPECT_EQ(clock.max_ticks_per_frame(), 15);  // a quarter of a second
    // 0.25 s owed: all of it runs.
    EXPECT_EQ(clock.advance(milliseconds(250)), 15);
    EXPECT_EQ(clock.dropped(), nanoseconds(0));
    // 0.4 s: 15 ticks run, the other 9 are dropped and said so.
    clock.reset();
    EXPECT_EQ(clock.advance(milliseconds(400)), 15);
    EXPECT_EQ(clock.dropped(), milliseconds(150));
    EXPECT_EQ(clock.pending(), nanoseconds(0));
    // The next normal frame is on time again.
    EXPECT_EQ(clock.advance(milliseconds(50)), 3);
    EXPECT_EQ(clock.dropped(), nanoseconds(0));
    // A stall of several seconds drops everything past the cap.
    EXPECT_EQ(clock.advance(std::chrono::seconds(5)), 15);
    EXPECT_EQ(clock.dropped(), milliseconds(4750));
}

TEST(FixedStepClock, AlphaIsTheFractionOfATickPending) {
    game::FixedStepClock clock(100);
    EXPECT_DOUBLE_EQ(clock.alpha(), 0.0);
    EXPECT_EQ(clock.advance(milliseconds(8)), 0);
    EXPECT_NEAR(clock.alpha(), 0.8, 1e-12);
    EXPECT_EQ(clock.advance(milliseconds(5)), 1);
    EXPECT_NEAR(clock.alpha(), 0.3, 1e-12);
    // Whatever the frames, alpha stays in [0, 1).
    game::FixedStepClock c60(60);
    for (int i = 0; i < 1000; ++i) {
        c60.advance(nanoseconds(1'000'000 + (int64_t(i) * 7'919'813) % 90'000'000));
        EXPECT_GE(c60.alpha(), 0.0);
        EXPECT_LT(c60.alpha(), 1.0);
    }
    clock.reset();
    EXPECT_DOUBLE_EQ(clock.alpha(), 0.0);
}

TEST(FixedStepClock, NegativeTimeAndReset) {
    game::FixedStepClock clock(100);
    EXPECT_EQ(clock.advance(milliseconds(-50)), 0);
    EXPECT_EQ(clock.advance(milliseconds(9)), 0);
    clock.reset();
    EXPECT_EQ(clock.pending(), nanoseconds(0));
    EXPECT_EQ(clock.advance(milliseconds(9)), 0);
    EXPECT_EQ(clock.advance(milliseconds(1)), 1);
    EXPECT_THROW(game::FixedStepClock(0), std::invalid_argument);
}

TEST(Hud, LinesShowStateSpeedAndQuality) {
    game::HudState hud;
    hud.speed_kmh = 42.4f;
    hud.vehicle = sim::Vehicle::Boat;
    hud.view = sim::ViewMode::Driver;
    hud.wipers = sim::WiperMode::Intermittent;
    hud.rain_intensity = 0.5f;
    hud.tick = 1234;
    hud.fps = 59.94;
    hud.quality = "auto";
    hud.render_scale = 0.65f;
    hud.render_width = 832;
    hud.render_height = 468;
    std::vector<std::string> lines = game::hud_lines(hud);
    ASSERT_EQ(lines.size(), 4u) << "the pass times are the debug panel's, not the HUD's";
    EXPECT_EQ(lines[0], "42 km/h  boat, driver view");
    EXPECT_EQ(lines[1], "wipers intermittent  rain 50%");
    EXPECT_EQ(lines[2], "tick 1234  59.9 fps");
    EXPECT_EQ(lines[3], "quality auto  scale 0.65 (832x468)");

    hud.paused = true;
    hud.recording = true;
    hud.status = "replay 5/10";
    lines = game::hud_lines(hud);
    EXPECT_EQ(lines[0].rfind("PAUSED  REC  replay 5/10", 0), 0u) << lines[0];

    hud = {};
    hud.behind = true;
    EXPECT_EQ(game::hud_lines(hud)[0].rfind("BEHIND REAL TIME", 0), 0u);
    hud.behind = false;
    hud.unfocused = true;
    EXPECT_EQ(game::hud_lines(hud)[0].rfind("PAUSED (window not focused)", 0), 0u);
    // Without a quality (no renderer) there is no quality line.
    for (const std::string& line : game::hud_lines(hud)) EXPECT_EQ(line.find("quality"), std::string::npos);
}

TEST(QualityChoice, NamesRoundTripAndAutoRunsMedium) {
    for (game::QualityChoice c : game::kQualityChoices)
        EXPECT_EQ(game::parse_quality_choice(game::quality_choice_name(c)), c);
    EXPECT_EQ(game::quality_choice_name(game::QualityChoice::Auto), "auto");
    EXPECT_EQ(game::preset_of(game::QualityChoice::Auto), effects::Quality::Medium);
    EXPECT_EQ(game::preset_of(game::QualityChoice::Low), effects::Quality::Low);
    EXPECT_EQ(game::preset_of(game::QualityChoice::High), effects::Quality::High);
    EXPECT_FALSE(game::parse_quality_choice("ultra").has_value());
    EXPECT_FALSE(game::parse_quality_choice("Auto").has_value());
    EXPECT_FALSE(game::parse_quality_choice("").has_value());
}

TEST(Hud, StateFollowsTheWorld) {
    sim::LevelDesc level;
    level.id = "play_test";
    level.car_spawn = {{0.0f, level.land_height_m, -40.0f}, 0.0f};
    level.boat_spawn = {{0.0f, 0.0f, 40.0f}, 0.0f};
    sim::World world(level);
    game::HudState hud = game::hud_state(world);
    EXPECT_EQ(hud.tick, 0u);
    EXPECT_EQ(hud.vehicle, sim::Vehicle::Car);
    EXPECT_EQ(hud.view, sim::ViewMode::Chase);
    EXPECT_FLOAT_EQ(hud.speed_kmh, 0.0f);

    const sim::TickInput throttle = keys({GLFW_KEY_W});
    for (int i = 0; i < 120; ++i) world.step(throttle);
    // The camera and rain keys act on their press edge.
    world.step(keys({GLFW_KEY_W, GLFW_KEY_C, GLFW_KEY_R}));
    hud = game::hud_state(world);
    EXPECT_EQ(hud.tick, 121u);
    EXPECT_GT(hud.speed_kmh, 10.0f);
    EXPECT_EQ(hud.view, sim::ViewMode::Driver);
    EXPECT_GT(hud.rain_intensity, 0.0f);
}

TEST(DebugUi, ParamsGroupedInRegistrationOrder) {
    float f = 0.0f;
    int i = 0;
    bool b = false;
    effects::ParamRegistry registry;
    registry.add("water", "choppiness", &f, 0.0f, 2.0f);
    registry.add("rain", "drops", &i, 0, 100);
    registry.add("water", "foam", &b);
    std::vector<game::ParamGroup> groups = game::group_params(registry.params());
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0].name, "water");
    EXPECT_EQ(groups[0].params, (std::vector<size_t>{0, 2}));
    EXPECT_EQ(groups[1].name, "rain");
    EXPECT_EQ(groups[1].params, (std::vector<size_t>{1}));
    EXPECT_TRUE(game::group_params({}).empty());
}

TEST(Screenshot, NamedByLocalDateAndTime) {
    std::tm local{};
    local.tm_year = 2024 - 1900;
    local.tm_mon = 2;
    local.tm_mday = 5;
    local.tm_hour = 14;
    local.tm_min = 7;
    local.tm_sec = 9;
    local.tm_isdst = -1;
    auto when = std::chrono::system_clock::from_time_t(std::mktime(&local)) + std::chrono::milliseconds(42);
    EXPECT_EQ(game::screenshot_path(when), fs::path("screenshots") / "spindrift_20240305-140709-042.png");
    EXPECT_NE(game::screenshot_path(when), game::screenshot_path(when + std::chrono::milliseconds(1)));
}

TEST(PlayCommand, DemoReplayArgsRenderEvery30thTick) {
    auto args = game::demo_replay_args("data/replays/harbour_drive.replay", 95, "spindrift-out/demo");
    EXPECT_EQ(args, (std::vector<std::string>{"data/replays/harbour_drive.replay", "--headless", "--frames",
                                              "30,60,90", "--out", "spindrift-out/demo"}));
    game::FrameSelection frames = game::FrameSelection::parse(args[3]);
    EXPECT_EQ(frames.ticks, (std::set<uint32_t>{30, 60, 90}));
    EXPECT_EQ(game::demo_replay_args("r", 12, "o")[3], "12");
    EXPECT_EQ(game::demo_replay_args("r", 0, "o")[3], "none");
    EXPECT_EQ(game::demo_replay_args("r", 60, "o")[3], "30,60");
}

TEST(PlayCommand, WithoutDisplayAMissingDemoReplayIsAClearError) {
    const fs::path empty = fs::temp_directory_path() / ("spindrift_play_test_" + std::to_string(::getpid()));
    fs::create_directories(empty);
    ScopedEnv display("DISPLAY", nullptr), wayland("WAYLAND_DISPLAY", nullptr);
    ScopedEnv data("SPINDRIFT_DATA", empty.c_str());
    ASSERT_FALSE(game::display_available());
    testing::internal::CaptureStderr();
    int code = game::play_command({});
    std::string err = testing::internal::GetCapturedStderr();
    fs::remove_all(empty);
    EXPECT_EQ(code, game::kExitBadInput);
    EXPECT_NE(err.find("harbour_drive.replay does not exist"), std::string::npos) << err;
}
