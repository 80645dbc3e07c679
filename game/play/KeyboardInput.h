#pragma once
// The keyboard in play mode: which GLFW keys hold which sim controls, and which keys
// act on the program itself (pause, screenshot, panels) rather than on the world.
#include <functional>
#include <optional>
#include <span>

#include "sim/core/TickInput.h"

namespace game {

// Up to two keys per control (e.g. W and Up); 0 marks an unused slot.
struct KeyBinding {
    sim::Control control;
    int keys[2];
};

// The bindings listed in `spindrift --help` (keys (play)).
std::span<const KeyBinding> key_bindings();

// The held controls for this tick given which GLFW keys are down. Pure: the play loop
// passes glfwGetKey, tests pass a set of keys.
sim::TickInput input_from_keys(const std::function<bool(int glfw_key)>& down);

// The control `glfw_key` is bound to, if any.
std::optional<sim::Control> control_for_key(int glfw_key);

// Keys that work on the program, acted on once per press.
enum class UiAction { Pause, Screenshot, ToggleDebugPanel, ToggleProfileTiming, ToggleAntialiasing, ToggleMute, Quit };

std::optional<UiAction> ui_action_for_key(int glfw_key);

}  // namespace game
