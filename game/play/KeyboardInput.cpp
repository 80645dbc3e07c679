#include "game/play/KeyboardInput.h"

namespace game {

sim::TickInput input_from_keys(const KeyBindings& bindings, const std::function<bool(int glfw_key)>& down) {
    sim::TickInput in;
    for (const ActionInfo& a : actions()) {
        if (!a.control) continue;
        bool held = false;
        for (int key : bindings.keys(a.action)) held = held || (key != 0 && down(key));
        // Left and right together both stay set: the sim steers by their difference.
        if (held) in.set(*a.control, true);
    }
    return in;
}

std::optional<sim::Control> control_for_key(const KeyBindings& bindings, int glfw_key) {
    const std::optional<Action> action = bindings.action_for(glfw_key);
    return action ? action_info(*action).control : std::nullopt;
}

std::optional<UiAction> ui_action_for_key(const KeyBindings& bindings, int glfw_key) {
    if (glfw_key == kMenuKey) return UiAction::Menu;
    const std::optional<Action> action = bindings.action_for(glfw_key);
    return action ? action_info(*action).ui : std::nullopt;
}

}  // namespace game
