#pragma once
// Keyboard keys by name, as the settings file and the Controls page spell them ("W",
// "Up", "Space", "F12"): GLFW's key codes, which name the key's place on a US layout.
#include <optional>
#include <string>
#include <string_view>

namespace game {

// Enter with Alt held: GLFW has no code for a chord, so the window reports this one
// (past GLFW_KEY_LAST) and bindings treat it as a key of its own.
inline constexpr int kKeyAltEnter = 349;

// The name of `glfw_key`, or "" for a key with none (0: unbound).
std::string key_name(int glfw_key);
// The key a name stands for (exact spelling, as key_name gives it).
std::optional<int> key_from_name(std::string_view name);

}  // namespace game
