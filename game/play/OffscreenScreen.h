#pragma once
#include "game/capture/FrameCapture.h"
#include "game/play/Screen.h"

namespace game {

// An RGBA8 framebuffer of a fixed size in the current (headless) context as the play
// loop's screen; it closes when asked to.
class OffscreenScreen final : public Screen {
public:
    OffscreenScreen(int width, int height) : size_{width, height}, target_(width, height) {}

    Size size() const override { return size_; }
    GLuint framebuffer() const override { return target_.output().framebuffer; }
    void handle_events(double /*wait_s*/) override {}
    // Nothing to swap: wait for the frame, as a swap on llvmpipe does.
    void present() override { glFinish(); }
    bool should_close() const override { return close_; }
    void request_close() override { close_ = true; }

    const FrameCapture& target() const { return target_; }

private:
    Size size_;
    FrameCapture target_;
    bool close_ = false;
};

}  // namespace game
