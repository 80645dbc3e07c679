#include "game/play/GamepadInput.h"

#include <algorithm>
#include <cmath>

namespace game {

namespace {

using sim::Control;

// Face buttons for what is pressed in a hurry, the bumpers for the views, the D-pad
// for the weather.
const GamepadBinding kBindings[] = {
    {GLFW_GAMEPAD_BUTTON_A, Control::SwitchVehicle, std::nullopt},
    {GLFW_GAMEPAD_BUTTON_X, Control::ThrowHeavy, std::nullopt},
    {GLFW_GAMEPAD_BUTTON_Y, Control::ThrowLight, std::nullopt},
    {GLFW_GAMEPAD_BUTTON_B, Control::Fire, std::nullopt},
    {GLFW_GAMEPAD_BUTTON_RIGHT_BUMPER, Control::Camera, std::nullopt},
    {GLFW_GAMEPAD_BUTTON_LEFT_BUMPER, Control::Wipers, std::nullopt},
    {GLFW_GAMEPAD_BUTTON_DPAD_UP, Control::RainUp, std::nullopt},
    {GLFW_GAMEPAD_BUTTON_DPAD_DOWN, Control::RainDown, std::nullopt},
    {GLFW_GAMEPAD_BUTTON_START, std::nullopt, UiAction::Menu},
    {GLFW_GAMEPAD_BUTTON_BACK, Control::Reset, std::nullopt},
};

bool down(const GLFWgamepadstate& pad, int button) { return pad.buttons[button] == GLFW_PRESS; }

int quantise_axis(float value, int full_scale) { return int(std::lround(value * float(full_scale))); }

}  // namespace

std::span<const GamepadBinding> gamepad_bindings() { return kBindings; }

float without_dead_zone(float value, float dead_zone) {
    if (!std::isfinite(value)) return 0.0f;
    const float magnitude = std::min(std::fabs(value), 1.0f);
    if (magnitude <= dead_zone) return 0.0f;
    const float scaled = (magnitude - dead_zone) / (1.0f - dead_zone);
    return value < 0.0f ? -scaled : scaled;
}

sim::TickInput gamepad_axes(const GLFWgamepadstate& pad) {
    // Triggers rest at -1 and are fully down at +1.
    const auto trigger = [&](int axis) {
        return without_dead_zone((pad.axes[axis] + 1.0f) * 0.5f, kTriggerDeadZone);
    };
    sim::TickInput in;
    in.throttle = uint8_t(quantise_axis(trigger(GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER), sim::kPedalFullScale));
    in.brake = uint8_t(quantise_axis(trigger(GLFW_GAMEPAD_AXIS_LEFT_TRIGGER), sim::kPedalFullScale));
    // GLFW's x grows to the right; the sim steers left with positive values.
    in.steer = int8_t(
        -quantise_axis(without_dead_zone(pad.axes[GLFW_GAMEPAD_AXIS_LEFT_X], kStickDeadZone), sim::kSteerFullScale));
    return in;
}

GamepadPresses gamepad_presses(const GLFWgamepadstate& before, const GLFWgamepadstate& now) {
    GamepadPresses presses;
    for (const GamepadBinding& b : kBindings) {
        if (!down(now, b.button) || down(before, b.button)) continue;
        if (b.control) presses.controls.push_back(*b.control);
        if (b.action) presses.actions.push_back(*b.action);
    }
    return presses;
}

}  // namespace game
