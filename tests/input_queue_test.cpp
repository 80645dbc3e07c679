// Every key press between two frames reaches the sim, in order, however few ticks the
// frames run: game/play/InputQueue.
#include <gtest/gtest.h>

#include <vector>

#include "SimTestLevel.h"
#include "game/play/InputQueue.h"
#include "sim/player/Player.h"
#include "sim/world/World.h"

using sim::Control;

namespace {

uint16_t bit(Control c) { return uint16_t(c); }

// How many times `c` rose over the inputs (the sim acts on each rise once).
int rises(const std::vector<sim::TickInput>& ticks, Control c) {
    int n = 0;
    bool last = false;
    for (const sim::TickInput& t : ticks) {
        n += t.has(c) && !last;
        last = t.has(c);
    }
    return n;
}

std::vector<sim::TickInput> run_ticks(game::InputQueue& q, int n) {
    std::vector<sim::TickInput> out;
    for (int i = 0; i < n; ++i) out.push_back(q.next_tick());
    return out;
}

}  // namespace

TEST(InputQueue, ThreePressesInOneSlowFrameStepTheWipersThreeTimes) {
    sim::World world(make_test_level());
    game::InputQueue q;
    // One frame: V pressed and released three times; the frame then runs 2 ticks, the
    // next ones 2 each, as a slow game would.
    for (int i = 0; i < 3; ++i) q.press(Control::Wipers);
    q.set_down({});
    std::vector<sim::TickInput> ticks;
    for (int frame = 0; frame < 4; ++frame)
        for (int t = 0; t < 2; ++t) {
            ticks.push_back(q.next_tick());
            world.step(ticks.back());
        }
    EXPECT_EQ(rises(ticks, Control::Wipers), 3);
    EXPECT_EQ(world.get<sim::Player>().wipers(), sim::WiperMode::High);  // off -> int -> low -> high
    EXPECT_EQ(q.waiting(), 0u);
}

TEST(InputQueue, EachPressGetsAHighTickThenALowOne) {
    game::InputQueue q;
    q.press(Control::Camera);
    q.press(Control::Camera);
    std::vector<sim::TickInput> ticks = run_ticks(q, 4);
    EXPECT_TRUE(ticks[0].has(Control::Camera));
    EXPECT_FALSE(ticks[1].has(Control::Camera));
    EXPECT_TRUE(ticks[2].has(Control::Camera));
    EXPECT_FALSE(ticks[3].has(Control::Camera));
}

TEST(InputQueue, PressesAFrameHasNoTicksForWaitForTheNext) {
    game::InputQueue q;
    for (int i = 0; i < 3; ++i) q.press(Control::Fire);
    std::vector<sim::TickInput> ticks = run_ticks(q, 1);  // a frame of one tick
    EXPECT_EQ(q.waiting(), 2u);
    // Frames without ticks (faster than 60 Hz) keep them too.
    for (const sim::TickInput& t : run_ticks(q, 4)) ticks.push_back(t);
    EXPECT_EQ(q.waiting(), 0u);
    EXPECT_EQ(rises(ticks, Control::Fire), 3);
}

TEST(InputQueue, PressesOfDifferentControlsRiseInTheOrderMade) {
    game::InputQueue q;
    q.press(Control::SwitchVehicle);
    q.press(Control::Camera);
    q.press(Control::SwitchVehicle);
    std::vector<sim::TickInput> ticks = run_ticks(q, 4);
    EXPECT_EQ(ticks[0].held, bit(Control::SwitchVehicle));
    EXPECT_EQ(ticks[1].held, bit(Control::Camera));
    EXPECT_EQ(ticks[2].held, bit(Control::SwitchVehicle));
    EXPECT_EQ(ticks[3].held, 0);
}

TEST(InputQueue, AOneShotKeyHeldDownStaysHeldWithoutNewEdges) {
    game::InputQueue q;
    q.press(Control::Wipers);
    q.set_down(sim::TickInput{bit(Control::Wipers)});
    std::vector<sim::TickInput> ticks = run_ticks(q, 10);
    EXPECT_EQ(rises(ticks, Control::Wipers), 1);
    EXPECT_TRUE(ticks.back().has(Control::Wipers));
    // A key found down without a press (held while the game was paused) never rises.
    game::InputQueue fresh;
    fresh.set_down(sim::TickInput{bit(Control::Fire)});
    EXPECT_EQ(rises(run_ticks(fresh, 5), Control::Fire), 0);
}

TEST(InputQueue, HeldControlsFollowTheKeysAndATapHoldsForOneTick) {
    game::InputQueue q;
    q.set_down(sim::TickInput{uint16_t(bit(Control::Throttle) | bit(Control::SteerLeft))});
    for (const sim::TickInput& t : run_ticks(q, 3))
        EXPECT_EQ(t.held, bit(Control::Throttle) | bit(Control::SteerLeft));
    q.set_down({});
    EXPECT_EQ(q.next_tick().held, 0);
    // Brake tapped and released between two ticks.
    q.press(Control::Brake);
    q.set_down({});
    EXPECT_EQ(q.next_tick().held, bit(Control::Brake));
    EXPECT_EQ(q.next_tick().held, 0);
    EXPECT_EQ(q.waiting(), 0u);  // held controls are never queued
}

TEST(InputQueue, ClearForgetsWaitingPressesAndTaps) {
    game::InputQueue q;
    q.press(Control::Fire);
    q.press(Control::Throttle);
    q.clear();
    EXPECT_EQ(q.waiting(), 0u);
    EXPECT_EQ(q.next_tick().held, 0);
}

TEST(InputQueue, ThePlayedInputsReplayToTheSameWorld) {
    // What the loop records is what it applied: stepping a second world with the
    // recorded inputs ends in the same hash.
    sim::World played(make_test_level()), replayed(make_test_level());
    game::InputQueue q;
    std::vector<sim::TickInput> recorded;
    for (int frame = 0; frame < 40; ++frame) {
        if (frame % 7 == 0) q.press(Control::Camera);
        if (frame % 5 == 0) q.press(Control::ThrowHeavy);
        q.set_down(sim::TickInput{frame < 30 ? bit(Control::Throttle) : uint16_t(0)});
        for (int t = 0; t < 1 + frame % 3; ++t) {
            recorded.push_back(sim::quantise(q.next_tick()));
            played.step(recorded.back());
        }
    }
    for (const sim::TickInput& in : recorded) replayed.step(in);
    EXPECT_EQ(played.hash().world, replayed.hash().world);
    EXPECT_EQ(rises(recorded, Control::Camera), 6);
    EXPECT_EQ(rises(recorded, Control::ThrowHeavy), 8);
}
