#include "game/play/WindowScreen.h"

namespace game {

Screen::Size WindowScreen::size() const {
    if (window_.minimised()) return {};
    const Window::Size s = window_.framebuffer_size();
    return {s.width, s.height};
}

void WindowScreen::handle_events(double wait_s) {
    if (wait_s > 0.0)
        window_.wait_events(wait_s);
    else
        window_.poll_events();
}

}  // namespace game
