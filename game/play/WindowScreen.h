#pragma once
#include <string>

#include "game/play/Screen.h"
#include "game/play/Window.h"

namespace game {

// A GLFW window as the play loop's screen.
class WindowScreen final : public Screen {
public:
    // Throws std::runtime_error when no window can be opened.
    explicit WindowScreen(const Window::Options& options) : window_(options) {}

    Size size() const override;
    GLuint framebuffer() const override { return 0; }
    void handle_events(double wait_s) override;
    void present() override { window_.swap_buffers(); }
    bool should_close() const override { return window_.should_close(); }
    void request_close() override { window_.request_close(); }

    std::vector<int> take_key_presses() override { return window_.take_key_presses(); }
    bool key_down(int glfw_key) const override { return window_.key_down(glfw_key); }
    bool read_gamepad(GLFWgamepadstate* state) const override { return window_.read_gamepad(state); }
    bool focused() const override { return window_.focused(); }
    bool take_activity() override { return window_.take_activity(); }
    void set_fullscreen(bool on) override { window_.set_fullscreen(on); }
    bool fullscreen() const override { return window_.fullscreen(); }
    void set_vsync(bool on) override { window_.set_vsync(on); }
    std::optional<std::array<int, 4>> windowed_placement() const override {
        const Window::Placement p = window_.windowed_placement();
        return std::array<int, 4>{p.x, p.y, p.width, p.height};
    }
    GLFWwindow* glfw_window() const override { return window_.handle(); }

private:
    Window window_;
};

}  // namespace game
