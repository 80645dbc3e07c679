#pragma once
// A GLFW window with an OpenGL 4.5 core context, current on the constructing thread.
// One at a time: it initialises GLFW and terminates it again.
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;
struct GLFWgamepadstate;

namespace game {

class Window {
public:
    struct Options {
        int width = 1280, height = 720;
        std::string title = "Spindrift";
        bool vsync = true;
        std::optional<int> x, y;  // where the window goes; none: where the window manager puts it
        bool fullscreen = false;
    };

    // Throws std::runtime_error naming the GLFW step and its message on failure.
    explicit Window(const Options& options);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }

    bool should_close() const;
    void request_close();
    void poll_events();
    // Sleeps until an event or `timeout_s` (a minimised window has no frames to pace it).
    void wait_events(double timeout_s);
    void swap_buffers();

    struct Size {
        int width = 0, height = 0;
    };
    // Pixels of the default framebuffer; 0 x 0 while minimised.
    Size framebuffer_size() const;

    // Whether `glfw_key` is down now (a tap between two polls shows only as a press).
    bool key_down(int glfw_key) const;
    // The first joystick GLFW knows a gamepad mapping for, read now; false if none is
    // connected.
    bool read_gamepad(GLFWgamepadstate* state) const;
    // Keys pressed (not auto-repeated) since the last call, in order.
    std::vector<int> take_key_presses();
    // False from losing the keyboard focus until it comes back. Starts true: a window
    // no window manager ever focused (Xvfb) still plays.
    bool focused() const { return focused_; }
    bool minimised() const;

    // Borderless fullscreen on the monitor the window is most on (its desktop mode, so
    // the display does not switch modes), and back to the window it was.
    void set_fullscreen(bool on);
    bool fullscreen() const;
    void set_vsync(bool on);
    // The window's place and size when not fullscreen (while fullscreen: where it
    // goes back to), in screen coordinates.
    struct Placement {
        int x = 0, y = 0, width = 0, height = 0;
    };
    Placement windowed_placement() const;
    // Whether any input or window event arrived since the last call: a paused game
    // draws a frame only then (the debug panel still answers the mouse).
    bool take_activity();

private:
    static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void on_focus(GLFWwindow* window, int focused);
    static void mark_activity(GLFWwindow* window);

    GLFWwindow* window_ = nullptr;
    Placement windowed_;  // kept while fullscreen
    std::vector<int> presses_;
    bool focused_ = true;
    bool activity_ = false;
};

}  // namespace game
