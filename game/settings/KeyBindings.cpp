#include "game/settings/KeyBindings.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "game/settings/KeyNames.h"

namespace game {

static_assert(kMenuKey == GLFW_KEY_ESCAPE);

namespace {

using sim::Control;

constexpr ActionInfo kActions[] = {
    {Action::Throttle, "throttle", "Throttle", Control::Throttle, {}, {GLFW_KEY_W, GLFW_KEY_UP}},
    {Action::Brake, "brake", "Brake / reverse", Control::Brake, {}, {GLFW_KEY_S, GLFW_KEY_DOWN}},
    {Action::SteerLeft, "steer_left", "Steer left", Control::SteerLeft, {}, {GLFW_KEY_A, GLFW_KEY_LEFT}},
    {Action::SteerRight, "steer_right", "Steer right", Control::SteerRight, {}, {GLFW_KEY_D, GLFW_KEY_RIGHT}},
    {Action::SwitchVehicle, "switch_vehicle", "Switch car / boat", Control::SwitchVehicle, {}, {GLFW_KEY_E, 0}},
    {Action::ThrowHeavy, "throw_heavy", "Throw heavy", Control::ThrowHeavy, {}, {GLFW_KEY_1, 0}},
    {Action::ThrowLight, "throw_light", "Throw light", Control::ThrowLight, {}, {GLFW_KEY_2, 0}},
    {Action::Fire, "fire", "Fire", Control::Fire, {}, {GLFW_KEY_SPACE, 0}},
    {Action::Camera, "camera", "Camera (chase / driver)", Control::Camera, {}, {GLFW_KEY_C, 0}},
    {Action::Wipers, "wipers", "Wipers", Control::Wipers, {}, {GLFW_KEY_V, 0}},
    {Action::RainUp, "rain_up", "Rain up", Control::RainUp, {}, {GLFW_KEY_R, 0}},
    {Action::RainDown, "rain_down", "Rain down", Control::RainDown, {}, {GLFW_KEY_F, 0}},
    {Action::Reset, "reset", "Reset the vehicle", Control::Reset, {}, {GLFW_KEY_BACKSPACE, 0}},
    {Action::Pause, "pause", "Pause", {}, UiAction::Pause, {GLFW_KEY_P, 0}},
    {Action::Mute, "mute", "Mute the sound", {}, UiAction::ToggleMute, {GLFW_KEY_M, 0}},
    {Action::Screenshot, "screenshot", "Screenshot", {}, UiAction::Screenshot, {GLFW_KEY_F12, 0}},
    {Action::DebugPanel, "debug_panel", "Debug panel", {}, UiAction::ToggleDebugPanel, {GLFW_KEY_F1, 0}},
    {Action::ProfileTiming, "profile_timing", "Profile timing", {}, UiAction::ToggleProfileTiming, {GLFW_KEY_F2, 0}},
    {Action::Antialiasing, "antialiasing", "Anti-aliasing on/off", {}, UiAction::ToggleAntialiasing, {GLFW_KEY_F3, 0}},
    {Action::Fullscreen, "fullscreen", "Fullscreen", {}, UiAction::Fullscreen, {GLFW_KEY_F11, kKeyAltEnter}},
};
static_assert(std::size(kActions) == kActionCount);

}  // namespace

std::span<const ActionInfo> actions() { return kActions; }

const ActionInfo& action_info(Action action) { return kActions[size_t(action)]; }

std::optional<Action> action_from_id(std::string_view id) {
    for (const ActionInfo& a : kActions)
        if (a.id == id) return a.action;
    return std::nullopt;
}

KeyBindings::KeyBindings() {
    for (const ActionInfo& a : kActions) keys_[size_t(a.action)] = a.default_keys;
}

std::optional<Action> KeyBindings::action_for(int key) const {
    if (key == 0) return std::nullopt;
    for (size_t i = 0; i < kActionCount; ++i)
        for (int k : keys_[i])
            if (k == key) return Action(i);
    return std::nullopt;
}

KeyBindings::Outcome KeyBindings::bind(Action action, int slot, int key) {
    const std::string name = key_name(key);
    const std::string_view label = action_info(action).label;
    if (slot < 0 || slot >= kSlots) return {false, "no such key slot"};
    if (key == kMenuKey) return {false, "Esc always opens the menu; it cannot be bound"};
    if (name.empty()) return {false, "that key has no name here; pick another"};
    Keys& mine = keys_[size_t(action)];
    const int old = mine[size_t(slot)];
    if (old == key) return {true, name + " already does " + std::string(label)};
    // The same action's other slot: the two slots trade places.
    const int other_slot = 1 - slot;
    if (mine[size_t(other_slot)] == key) {
        mine[size_t(other_slot)] = old;
        mine[size_t(slot)] = key;
        return {true, std::string(label) + ": " + name + " moved to the other slot"};
    }
    std::string message = std::string(label) + ": " + name;
    if (std::optional<Action> owner = action_for(key)) {
        Keys& theirs = keys_[size_t(*owner)];
        for (int& k : theirs)
            if (k == key) k = old;
        const std::string_view their_label = action_info(*owner).label;
        message += old ? " (swapped: " + std::string(their_label) + " now has " + key_name(old) + ")"
                       : " (taken from " + std::string(their_label) + ")";
    }
    mine[size_t(slot)] = key;
    return {true, message};
}

void KeyBindings::unbind(Action action, int slot) {
    if (slot >= 0 && slot < kSlots) keys_[size_t(action)][size_t(slot)] = 0;
}

std::optional<std::pair<Action, Action>> KeyBindings::first_shared_key() const {
    for (size_t i = 0; i < kActionCount; ++i)
        for (size_t s = 0; s < size_t(kSlots); ++s) {
            const int key = keys_[i][s];
            if (key == 0) continue;
            if (s == 1 && keys_[i][0] == key) return std::pair{Action(i), Action(i)};
            for (size_t j = 0; j < i; ++j)
                for (int k : keys_[j])
                    if (k == key) return std::pair{Action(j), Action(i)};
        }
    return std::nullopt;
}

}  // namespace game
