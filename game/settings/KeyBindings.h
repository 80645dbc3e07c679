#pragma once
// Which keyboard keys do what in play: every action (a sim control, or one on the
// program such as pause or fullscreen) has up to two keys, and no key does two things.
// Esc is not among them: it always opens the menu, so a player can never bind
// themselves out of the game.
#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "sim/core/TickInput.h"

namespace game {

// Keys that work on the program, acted on once per press.
enum class UiAction { Menu, Pause, Screenshot, ToggleDebugPanel, ToggleProfileTiming, ToggleAntialiasing, Fullscreen, ToggleMute };

enum class Action : uint8_t {
    Throttle, Brake, SteerLeft, SteerRight, SwitchVehicle, ThrowHeavy, ThrowLight, Fire, Camera, Wipers,
    RainUp, RainDown, Reset, Pause, Mute, Screenshot, DebugPanel, ProfileTiming, Antialiasing, Fullscreen,
};
inline constexpr size_t kActionCount = 20;

struct ActionInfo {
    Action action;
    std::string_view id;     // its key in the settings file
    std::string_view label;  // what the Controls page calls it
    std::optional<sim::Control> control;  // exactly one of control and ui is set
    std::optional<UiAction> ui;
    std::array<int, 2> default_keys;      // 0: none
};

// Every action, in the Controls page's order.
std::span<const ActionInfo> actions();
const ActionInfo& action_info(Action action);
std::optional<Action> action_from_id(std::string_view id);

// The key that opens the menu (and closes it): fixed.
inline constexpr int kMenuKey = 256;  // GLFW_KEY_ESCAPE

class KeyBindings {
public:
    static constexpr int kSlots = 2;
    using Keys = std::array<int, kSlots>;

    KeyBindings();  // the defaults

    const Keys& keys(Action action) const { return keys_[size_t(action)]; }
    std::optional<Action> action_for(int key) const;

    // What bind() did, in a line for the player.
    struct Outcome {
        bool bound = false;
        std::string message;
    };
    // Puts `key` in `action`'s `slot`. A key another action has is taken from it, and
    // that action gets this slot's old key in its place (a swap, said in the message);
    // Esc and unnamed keys are refused.
    Outcome bind(Action action, int slot, int key);
    void unbind(Action action, int slot);

    // Replaces one action's keys without looking at the others (the settings file's
    // reader, which checks for shared keys itself); `keys` must be nameable.
    void set_keys(Action action, const Keys& keys) { keys_[size_t(action)] = keys; }
    // An action that shares a key with an earlier one, if any.
    std::optional<std::pair<Action, Action>> first_shared_key() const;

    bool operator==(const KeyBindings&) const = default;

private:
    std::array<Keys, kActionCount> keys_;
};

}  // namespace game
