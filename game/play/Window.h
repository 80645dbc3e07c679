#pragma once
// A GLFW window with an OpenGL 4.5 core context, current on the constructing thread.
// One at a time: it initialises GLFW and terminates it again.
#include <string>
#include <vector>

struct GLFWwindow;

namespace game {

class Window {
public:
    struct Options {
        int width = 1280, height = 720;
        std::string title = "Spindrift";
        bool vsync = true;
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

    // Whether `glfw_key` is down, or was pressed since it was last asked about (sticky
    // keys): a tap shorter than a tick still reaches the sim.
    bool key_down(int glfw_key) const;
    // Keys pressed (not auto-repeated) since the last call, in order.
    std::vector<int> take_key_presses();

private:
    static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);

    GLFWwindow* window_ = nullptr;
    std::vector<int> presses_;
};

}  // namespace game
