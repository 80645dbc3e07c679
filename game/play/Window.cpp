#include "game/play/Window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <stdexcept>

#include "game/settings/KeyNames.h"

namespace game {

namespace {

// GLFW reports errors through a callback; keep the last one for the exception text.
std::string g_last_glfw_error;

void on_glfw_error(int code, const char* description) {
    g_last_glfw_error = std::string(description ? description : "unknown error") + " (GLFW error " +
                        std::to_string(code) + ")";
}

[[noreturn]] void fail(const std::string& step) {
    std::string why = g_last_glfw_error.empty() ? "no reason given" : g_last_glfw_error;
    throw std::runtime_error("cannot open a window: " + step + " failed: " + why);
}

}  // namespace

Window::Window(const Options& options) {
    g_last_glfw_error.clear();
    glfwSetErrorCallback(on_glfw_error);
    if (!glfwInit()) fail("glfwInit");
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
    window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        fail("creating a " + std::to_string(options.width) + "x" + std::to_string(options.height) +
             " window with an OpenGL 4.5 core context");
    }
    if (options.x && options.y) glfwSetWindowPos(window_, *options.x, *options.y);
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(options.vsync ? 1 : 0);
    glfwSetWindowUserPointer(window_, this);
    // Installed before Dear ImGui's, which chains to them.
    glfwSetKeyCallback(window_, on_key);
    glfwSetWindowFocusCallback(window_, on_focus);
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double, double) { mark_activity(w); });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int, int, int) { mark_activity(w); });
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double) { mark_activity(w); });
    glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned int) { mark_activity(w); });
    glfwSetWindowRefreshCallback(window_, mark_activity);
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { mark_activity(w); });
    if (options.fullscreen) set_fullscreen(true);
}

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
    glfwSetErrorCallback(nullptr);
}

bool Window::should_close() const { return glfwWindowShouldClose(window_) != 0; }
void Window::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::poll_events() { glfwPollEvents(); }
void Window::wait_events(double timeout_s) { glfwWaitEventsTimeout(timeout_s); }
void Window::swap_buffers() { glfwSwapBuffers(window_); }

Window::Size Window::framebuffer_size() const {
    Size s;
    glfwGetFramebufferSize(window_, &s.width, &s.height);
    return s;
}

bool Window::key_down(int glfw_key) const { return glfwGetKey(window_, glfw_key) == GLFW_PRESS; }

bool Window::read_gamepad(GLFWgamepadstate* state) const {
    for (int jid = GLFW_JOYSTICK_1; jid <= GLFW_JOYSTICK_LAST; ++jid)
        if (glfwJoystickIsGamepad(jid) && glfwGetGamepadState(jid, state)) return true;
    return false;
}

bool Window::minimised() const { return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) != 0; }

namespace {

// The monitor holding most of the window (the primary one if it is on none).
GLFWmonitor* monitor_under(GLFWwindow* window) {
    int wx = 0, wy = 0, ww = 0, wh = 0;
    glfwGetWindowPos(window, &wx, &wy);
    glfwGetWindowSize(window, &ww, &wh);
    int count = 0;
    GLFWmonitor** monitors = glfwGetMonitors(&count);
    GLFWmonitor* best = glfwGetPrimaryMonitor();
    long best_area = 0;
    for (int i = 0; i < count; ++i) {
        const GLFWvidmode* mode = glfwGetVideoMode(monitors[i]);
        if (!mode) continue;
        int mx = 0, my = 0;
        glfwGetMonitorPos(monitors[i], &mx, &my);
        const long w = std::max(0, std::min(wx + ww, mx + mode->width) - std::max(wx, mx));
        const long h = std::max(0, std::min(wy + wh, my + mode->height) - std::max(wy, my));
        if (w * h > best_area) {
            best_area = w * h;
            best = monitors[i];
        }
    }
    return best;
}

}  // namespace

bool Window::fullscreen() const { return glfwGetWindowMonitor(window_) != nullptr; }

void Window::set_fullscreen(bool on) {
    if (on == fullscreen()) return;
    if (on) {
        windowed_ = windowed_placement();
        GLFWmonitor* monitor = monitor_under(window_);
        const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
        if (!mode) return;  // no monitor to fill: stay a window
        glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
    } else {
        glfwSetWindowMonitor(window_, nullptr, windowed_.x, windowed_.y, windowed_.width, windowed_.height, 0);
    }
    activity_ = true;
}

void Window::set_vsync(bool on) { glfwSwapInterval(on ? 1 : 0); }

Window::Placement Window::windowed_placement() const {
    if (fullscreen()) return windowed_;
    Placement p;
    glfwGetWindowPos(window_, &p.x, &p.y);
    glfwGetWindowSize(window_, &p.width, &p.height);
    return p;
}

bool Window::take_activity() {
    const bool any = activity_;
    activity_ = false;
    return any;
}

std::vector<int> Window::take_key_presses() {
    std::vector<int> out;
    out.swap(presses_);
    return out;
}

void Window::on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
    if (!self) return;
    self->activity_ = true;
    if (key == GLFW_KEY_ENTER && (mods & GLFW_MOD_ALT)) key = kKeyAltEnter;  // a chord, bound as one key
    if (action == GLFW_PRESS && key != GLFW_KEY_UNKNOWN) self->presses_.push_back(key);
}

void Window::on_focus(GLFWwindow* window, int focused) {
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
    if (!self) return;
    self->focused_ = focused != 0;
    self->activity_ = true;
}

void Window::mark_activity(GLFWwindow* window) {
    if (auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window))) self->activity_ = true;
}

}  // namespace game
