#pragma once
// The menu Esc (or the gamepad's Start) opens over a stopped world: Resume, Settings,
// Controls, Restart the course, Quit. Its Settings and Controls pages edit the
// player's Settings in place; the play loop applies and keeps what changed.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "game/settings/Settings.h"

namespace game {

class PauseMenu {
public:
    enum class Choice { None, Resume, Restart, Quit };

    bool is_open() const { return open_; }
    void open();
    void close();

    // Waiting for the key to bind (a Controls page button was pressed): the loop gives
    // it the next key pressed instead of acting on it.
    bool capturing_key() const { return capture_.has_value(); }
    // The key pressed while capturing: bound to the action waiting for one (Esc cancels).
    void key_pressed(int glfw_key, Settings& settings);

    // A key went down (the window's press, in order). Dear ImGui 1.86 reads keys as
    // they are at each frame, so a tap that went up before the next frame would never
    // reach it (at llvmpipe's 10 frames a second, most taps): it is held for one frame.
    void tap(int glfw_key);

    struct Context {
        bool can_restart = false;
        std::function<bool(int glfw_key)> key_down;  // whether a key is down now
        std::string settings_path;  // where changes are kept; empty: they are not
        std::string settings_error; // the last save's failure, if any
    };
    // Draws the open menu (nothing when closed) in the current ImGui frame, editing
    // `settings`. Returns what the player chose this frame.
    Choice draw(Settings& settings, const Context& context);

private:
    enum class Page { Main, Settings, Controls };

    Choice draw_main(const Context& context);
    void draw_settings(Settings& settings, const Context& context);
    void draw_controls(Settings& settings);

    bool open_ = false;
    bool focus_first_ = false;  // put the keyboard/gamepad focus on the page's first item
    Page page_ = Page::Main;
    struct Capture {
        Action action;
        int slot;
    };
    std::optional<Capture> capture_;
    std::string message_;  // the last rebinding's outcome
    std::vector<int> tapped_;  // keys tap() held for this frame
};

// The first start's one line, "Esc: menu and controls", at the foot of the screen;
// it fades out over its last second (`seconds_left` to go).
void draw_menu_hint(float seconds_left);

// The gamepad's buttons (or axes) for an action, as the Controls page names them;
// "" for none.
std::string gamepad_name(Action action);

}  // namespace game
