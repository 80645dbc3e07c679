#pragma once
#include <string>

namespace game {

// An OpenGL 4.5 core context with no window and no default framebuffer (EGL
// surfaceless, Mesa): render into framebuffer objects. Current on the constructing
// thread. Throws std::runtime_error naming the EGL step and error on failure.
class HeadlessContext {
public:
    struct Options {
        bool debug = false;  // debug context: the driver reports more through KHR_debug
    };

    HeadlessContext() : HeadlessContext(Options{}) {}
    explicit HeadlessContext(Options options);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    // Makes this context current again (after another context was made current).
    void make_current();

    const std::string& renderer() const { return renderer_; }  // GL_RENDERER
    const std::string& version() const { return version_; }    // GL_VERSION
    bool debug() const { return debug_; }

    static const char* egl_error_name(int error);

private:
    void* display_ = nullptr;  // EGLDisplay
    void* context_ = nullptr;  // EGLContext
    bool debug_ = false;
    std::string renderer_;
    std::string version_;
};

}  // namespace game
