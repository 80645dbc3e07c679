#pragma once
// Where the play loop's frames go: a window, or an offscreen target of a fixed size
// (the timedemo without a display). The GL context is current before one is made.
#include <array>
#include <optional>
#include <vector>

#include "effects/gl/Gl.h"

struct GLFWwindow;
struct GLFWgamepadstate;

namespace game {

class Screen {
public:
    struct Size {
        int width = 0, height = 0;
    };

    virtual ~Screen() = default;

    // Pixels of the framebuffer frames go to; 0 x 0 while a window is minimised.
    virtual Size size() const = 0;
    virtual GLuint framebuffer() const = 0;
    // Handles pending events; with `wait_s` > 0 first sleeps until one comes or that
    // time passes (an idle game then costs no CPU).
    virtual void handle_events(double wait_s) = 0;
    // Shows the frame drawn; returns once it is finished, so frames are timed whole.
    virtual void present() = 0;
    virtual bool should_close() const = 0;
    virtual void request_close() = 0;

    // Input: none offscreen.
    virtual std::vector<int> take_key_presses() { return {}; }
    virtual bool key_down(int /*glfw_key*/) const { return false; }
    // The first connected gamepad's state into `state`; false if there is none.
    virtual bool read_gamepad(GLFWgamepadstate* /*state*/) const { return false; }
    virtual bool focused() const { return true; }
    // Whether anything (input, an expose) happened since the last call.
    virtual bool take_activity() { return false; }
    // A window's fullscreen and vsync; offscreen there is neither.
    virtual void set_fullscreen(bool /*on*/) {}
    virtual bool fullscreen() const { return false; }
    virtual void set_vsync(bool /*on*/) {}
    // A window's place and size when not fullscreen (x, y, width, height); none offscreen.
    virtual std::optional<std::array<int, 4>> windowed_placement() const { return std::nullopt; }
    // The window for Dear ImGui's platform backend; none offscreen.
    virtual GLFWwindow* glfw_window() const { return nullptr; }
};

}  // namespace game
