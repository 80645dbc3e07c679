#pragma once
// The keyboard in play mode: which keys hold which sim controls, and which act on the
// program itself (menu, pause, screenshot, panels) rather than on the world, as the
// player's KeyBindings say.
#include <functional>
#include <optional>

#include "game/settings/KeyBindings.h"
#include "sim/core/TickInput.h"

namespace game {

// The held controls for this tick given which GLFW keys are down. Pure: the play loop
// passes glfwGetKey, tests pass a set of keys.
sim::TickInput input_from_keys(const KeyBindings& bindings, const std::function<bool(int glfw_key)>& down);

// The control `glfw_key` is bound to, if any.
std::optional<sim::Control> control_for_key(const KeyBindings& bindings, int glfw_key);

// The program's action for `glfw_key` (Esc: the menu), if any.
std::optional<UiAction> ui_action_for_key(const KeyBindings& bindings, int glfw_key);

}  // namespace game
