#include "game/play/KeyboardInput.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace game {

namespace {

using sim::Control;

constexpr KeyBinding kBindings[] = {
    {Control::Throttle, {GLFW_KEY_W, GLFW_KEY_UP}},
    {Control::Brake, {GLFW_KEY_S, GLFW_KEY_DOWN}},
    {Control::SteerLeft, {GLFW_KEY_A, GLFW_KEY_LEFT}},
    {Control::SteerRight, {GLFW_KEY_D, GLFW_KEY_RIGHT}},
    {Control::SwitchVehicle, {GLFW_KEY_E, 0}},
    {Control::ThrowHeavy, {GLFW_KEY_1, 0}},
    {Control::ThrowLight, {GLFW_KEY_2, 0}},
    {Control::Fire, {GLFW_KEY_SPACE, 0}},
    {Control::Camera, {GLFW_KEY_C, 0}},
    {Control::Wipers, {GLFW_KEY_V, 0}},
    {Control::RainUp, {GLFW_KEY_R, 0}},
    {Control::RainDown, {GLFW_KEY_F, 0}},
    {Control::Reset, {GLFW_KEY_BACKSPACE, 0}},
};

}  // namespace

std::span<const KeyBinding> key_bindings() { return kBindings; }

sim::TickInput input_from_keys(const std::function<bool(int glfw_key)>& down) {
    sim::TickInput in;
    for (const KeyBinding& b : kBindings) {
        bool held = false;
        for (int key : b.keys) held = held || (key != 0 && down(key));
        // Left and right together both stay set: the sim steers by their difference.
        if (held) in.set(b.control, true);
    }
    return in;
}

std::optional<sim::Control> control_for_key(int glfw_key) {
    for (const KeyBinding& b : kBindings)
        for (int key : b.keys)
            if (key != 0 && key == glfw_key) return b.control;
    return std::nullopt;
}

std::optional<UiAction> ui_action_for_key(int glfw_key) {
    switch (glfw_key) {
        case GLFW_KEY_P: return UiAction::Pause;
        case GLFW_KEY_F12: return UiAction::Screenshot;
        case GLFW_KEY_F1: return UiAction::ToggleDebugPanel;
        case GLFW_KEY_F2: return UiAction::ToggleProfileTiming;
        case GLFW_KEY_F3: return UiAction::ToggleAntialiasing;
        case GLFW_KEY_M: return UiAction::ToggleMute;
        case GLFW_KEY_ESCAPE: return UiAction::Quit;
        default: return std::nullopt;
    }
}

}  // namespace game
