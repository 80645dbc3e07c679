// The gamepad without a device: a made GLFWgamepadstate through the dead zones and the
// quantisation to a tick's analog axes, button presses as rising edges, and the axes
// carried by the input queue into every tick.
#include "game/play/GamepadInput.h"
#include "game/play/InputQueue.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace {

using game::UiAction;
using sim::Control;

// A pad at rest: sticks centred, triggers up (GLFW reports a released trigger as -1).
GLFWgamepadstate at_rest() {
    GLFWgamepadstate pad{};
    pad.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] = -1.0f;
    pad.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] = -1.0f;
    return pad;
}

// A trigger pressed `amount` of its travel (0 up .. 1 down), as GLFW reports it.
float trigger(float amount) { return amount * 2.0f - 1.0f; }

TEST(Gamepad, AtRestGivesNoInput) { EXPECT_EQ(game::gamepad_axes(at_rest()), sim::TickInput{}); }

TEST(Gamepad, DeadZonesSwallowRestingNoiseAndKeepFullTravelFullScale) {
    EXPECT_EQ(game::without_dead_zone(0.1f, 0.15f), 0.0f);
    EXPECT_EQ(game::without_dead_zone(-0.15f, 0.15f), 0.0f);
    EXPECT_EQ(game::without_dead_zone(1.0f, 0.15f), 1.0f);
    EXPECT_EQ(game::without_dead_zone(-1.0f, 0.15f), -1.0f);
    EXPECT_EQ(game::without_dead_zone(1.3f, 0.15f), 1.0f);  // a pad reporting past its range
    EXPECT_EQ(game::without_dead_zone(std::nanf(""), 0.15f), 0.0f);
    EXPECT_NEAR(game::without_dead_zone(0.575f, 0.15f), 0.5f, 1e-6f);  // linear beyond it
    EXPECT_NEAR(game::without_dead_zone(-0.575f, 0.15f), -0.5f, 1e-6f);

    GLFWgamepadstate pad = at_rest();
    pad.axes[GLFW_GAMEPAD_AXIS_LEFT_X] = 0.12f;  // a worn stick resting off centre
    pad.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] = trigger(0.04f);
    EXPECT_EQ(game::gamepad_axes(pad), sim::TickInput{});
}

TEST(Gamepad, TriggersAndStickAreQuantisedToTheTicksSteps) {
    GLFWgamepadstate pad = at_rest();
    pad.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] = trigger(1.0f);
    pad.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] = trigger(0.05f + 0.95f * 0.6f);  // 60% past the dead zone
    pad.axes[GLFW_GAMEPAD_AXIS_LEFT_X] = -1.0f;  // full left
    sim::TickInput in = game::gamepad_axes(pad);
    EXPECT_EQ(in.held, 0);  // the axes only: buttons act through presses
    EXPECT_EQ(in.throttle, 255);
    EXPECT_EQ(in.brake, 153);  // 0.6 * 255
    EXPECT_EQ(in.steer, 127);  // left is positive, as the sim steers
    EXPECT_EQ(sim::steer_amount(in), 1.0f);
    EXPECT_EQ(sim::throttle_amount(in), 1.0f);

    pad.axes[GLFW_GAMEPAD_AXIS_LEFT_X] = 0.15f + 0.85f * 0.25f;  // a quarter right
    in = game::gamepad_axes(pad);
    EXPECT_EQ(in.steer, -32);  // round(-0.25 * 127)
    EXPECT_EQ(sim::quantise(in), in);
    pad.axes[GLFW_GAMEPAD_AXIS_LEFT_X] = 1.0f;
    EXPECT_EQ(game::gamepad_axes(pad).steer, -127);
}

TEST(Gamepad, ButtonsPressOnTheirRisingEdgeOnly) {
    GLFWgamepadstate before = at_rest(), now = at_rest();
    now.buttons[GLFW_GAMEPAD_BUTTON_A] = GLFW_PRESS;
    now.buttons[GLFW_GAMEPAD_BUTTON_START] = GLFW_PRESS;
    game::GamepadPresses p = game::gamepad_presses(before, now);
    EXPECT_EQ(p.controls, std::vector<Control>{Control::SwitchVehicle});
    EXPECT_EQ(p.actions, std::vector<UiAction>{UiAction::Menu});
    // Held down: no new press.
    p = game::gamepad_presses(now, now);
    EXPECT_TRUE(p.controls.empty());
    EXPECT_TRUE(p.actions.empty());
    // Released, then pressed again: another press.
    EXPECT_TRUE(game::gamepad_presses(now, before).controls.empty());
    EXPECT_EQ(game::gamepad_presses(before, now).controls.size(), 1u);
}

TEST(Gamepad, EveryOneShotControlHasOneButtonAndNoButtonTwoUses) {
    std::set<int> buttons;
    std::set<Control> controls;
    for (const game::GamepadBinding& b : game::gamepad_bindings()) {
        EXPECT_TRUE(buttons.insert(b.button).second) << "button " << b.button << " bound twice";
        EXPECT_NE(b.control.has_value(), b.action.has_value()) << "button " << b.button;
        EXPECT_GE(b.button, 0);
        EXPECT_LE(b.button, GLFW_GAMEPAD_BUTTON_LAST);
        if (b.control) {
            EXPECT_TRUE(uint16_t(*b.control) & sim::kOneShotControls) << "held controls are axes";
            EXPECT_TRUE(controls.insert(*b.control).second);
        }
    }
    for (int i = 0; i < sim::kControlCount; ++i) {
        const auto c = static_cast<Control>(1u << i);
        if (uint16_t(c) & sim::kOneShotControls) {
            EXPECT_TRUE(controls.count(c)) << sim::kControlNames[i];
        }
    }
}

TEST(Gamepad, TheQueueCarriesTheAxesIntoEveryTickBesideTheKeys) {
    game::InputQueue q;
    sim::TickInput down;
    down.set(Control::SteerLeft, true);  // a key held while the pad throttles
    down.throttle = 200;
    down.steer = -40;
    q.set_down(down);
    q.press(Control::Fire);
    const sim::TickInput first = q.next_tick(), second = q.next_tick();
    EXPECT_TRUE(first.has(Control::Fire));
    EXPECT_FALSE(second.has(Control::Fire));
    for (const sim::TickInput& t : {first, second}) {
        EXPECT_TRUE(t.has(Control::SteerLeft));
        EXPECT_EQ(t.throttle, 200);
        EXPECT_EQ(t.brake, 0);
        EXPECT_EQ(t.steer, -40);
    }
    q.set_down({});  // the pad let go
    EXPECT_EQ(q.next_tick(), sim::TickInput{});
}

}  // namespace
