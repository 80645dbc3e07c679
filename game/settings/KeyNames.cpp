#include "game/settings/KeyNames.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <utility>
#include <vector>

namespace game {

static_assert(kKeyAltEnter == GLFW_KEY_LAST + 1);

namespace {

// Keys without a one-character name; letters, digits and F1..F25 are made below.
constexpr std::pair<int, std::string_view> kNamed[] = {
    {GLFW_KEY_SPACE, "Space"},          {GLFW_KEY_APOSTROPHE, "'"},          {GLFW_KEY_COMMA, ","},
    {GLFW_KEY_MINUS, "-"},              {GLFW_KEY_PERIOD, "."},              {GLFW_KEY_SLASH, "/"},
    {GLFW_KEY_SEMICOLON, ";"},          {GLFW_KEY_EQUAL, "="},               {GLFW_KEY_LEFT_BRACKET, "["},
    {GLFW_KEY_BACKSLASH, "\\"},         {GLFW_KEY_RIGHT_BRACKET, "]"},       {GLFW_KEY_GRAVE_ACCENT, "`"},
    {GLFW_KEY_ESCAPE, "Esc"},           {GLFW_KEY_ENTER, "Enter"},           {GLFW_KEY_TAB, "Tab"},
    {GLFW_KEY_BACKSPACE, "Backspace"},  {GLFW_KEY_INSERT, "Insert"},         {GLFW_KEY_DELETE, "Delete"},
    {GLFW_KEY_RIGHT, "Right"},          {GLFW_KEY_LEFT, "Left"},             {GLFW_KEY_DOWN, "Down"},
    {GLFW_KEY_UP, "Up"},                {GLFW_KEY_PAGE_UP, "PageUp"},        {GLFW_KEY_PAGE_DOWN, "PageDown"},
    {GLFW_KEY_HOME, "Home"},            {GLFW_KEY_END, "End"},               {GLFW_KEY_CAPS_LOCK, "CapsLock"},
    {GLFW_KEY_SCROLL_LOCK, "ScrollLock"}, {GLFW_KEY_NUM_LOCK, "NumLock"},    {GLFW_KEY_PRINT_SCREEN, "PrintScreen"},
    {GLFW_KEY_PAUSE, "Pause"},          {GLFW_KEY_KP_DECIMAL, "Keypad."},    {GLFW_KEY_KP_DIVIDE, "Keypad/"},
    {GLFW_KEY_KP_MULTIPLY, "Keypad*"},  {GLFW_KEY_KP_SUBTRACT, "Keypad-"},   {GLFW_KEY_KP_ADD, "Keypad+"},
    {GLFW_KEY_KP_ENTER, "KeypadEnter"}, {GLFW_KEY_KP_EQUAL, "Keypad="},      {GLFW_KEY_LEFT_SHIFT, "LeftShift"},
    {GLFW_KEY_LEFT_CONTROL, "LeftCtrl"}, {GLFW_KEY_LEFT_ALT, "LeftAlt"},     {GLFW_KEY_LEFT_SUPER, "LeftSuper"},
    {GLFW_KEY_RIGHT_SHIFT, "RightShift"}, {GLFW_KEY_RIGHT_CONTROL, "RightCtrl"}, {GLFW_KEY_RIGHT_ALT, "RightAlt"},
    {GLFW_KEY_RIGHT_SUPER, "RightSuper"}, {GLFW_KEY_MENU, "Menu"},           {kKeyAltEnter, "Alt+Enter"},
};

}  // namespace

std::string key_name(int key) {
    if ((key >= GLFW_KEY_A && key <= GLFW_KEY_Z) || (key >= GLFW_KEY_0 && key <= GLFW_KEY_9))
        return std::string(1, char(key));  // GLFW's codes for these are their ASCII
    // Appended rather than "F" + to_string(): GCC 12 warns falsely (-Wrestrict) about that.
    std::string name;
    if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F25) return name.append("F").append(std::to_string(key - GLFW_KEY_F1 + 1));
    if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9)
        return name.append("Keypad").append(std::to_string(key - GLFW_KEY_KP_0));
    for (const auto& [code, known] : kNamed)
        if (code == key) return std::string(known);
    return "";
}

std::optional<int> key_from_name(std::string_view name) {
    // Few enough keys to ask each one its name.
    for (int key = GLFW_KEY_SPACE; key <= kKeyAltEnter; ++key)
        if (!name.empty() && key_name(key) == name) return key;
    return std::nullopt;
}

}  // namespace game
