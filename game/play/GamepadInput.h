#pragma once
// A gamepad in play mode, through GLFW's gamepad API (its built-in SDL mappings give
// every known pad the same layout): the triggers and the left stick become the tick's
// quantised analog throttle, brake and steering; buttons press the one-shot controls
// and pause. Pure: the play loop passes glfwGetGamepadState's state, tests a made one.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <optional>
#include <span>
#include <vector>

#include "game/play/KeyboardInput.h"
#include "sim/core/TickInput.h"

namespace game {

// Sticks rest a little off centre and triggers a little off their stop: inside these
// the axis reads zero, and beyond them it is rescaled so that full travel is still full
// scale.
inline constexpr float kStickDeadZone = 0.15f;
inline constexpr float kTriggerDeadZone = 0.05f;

// A button and what it does: a sim control or an action on the program.
struct GamepadBinding {
    int button;  // GLFW_GAMEPAD_BUTTON_*
    std::optional<sim::Control> control;
    std::optional<UiAction> action;
};

// The bindings, in the README's order.
std::span<const GamepadBinding> gamepad_bindings();

// `value` (-1..1 for a stick, as GLFW reports it) with the dead zone removed: 0 inside
// it, then linear to +-1 at full travel.
float without_dead_zone(float value, float dead_zone);

// The analog axes of `pad`: right trigger throttle, left trigger brake, left stick
// steering (pushed left is positive, as sim::DriveInput::steer), quantised to the
// tick's steps. No held bits: the buttons act through presses.
sim::TickInput gamepad_axes(const GLFWgamepadstate& pad);

// Buttons that went down between `before` and `now`, in the bindings' order.
struct GamepadPresses {
    std::vector<sim::Control> controls;
    std::vector<UiAction> actions;
};
GamepadPresses gamepad_presses(const GLFWgamepadstate& before, const GLFWgamepadstate& now);

}  // namespace game
