#include "game/platform/HeadlessContext.h"

#include "effects/gl/Gl.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <mutex>
#include <stdexcept>
#include <string_view>

namespace game {
namespace {

// EGL displays are per process: terminating one ends every context on it, so the
// display is terminated only when the last HeadlessContext goes.
std::mutex g_display_mutex;
int g_live_contexts = 0;

// Under LeakSanitizer the display is never terminated: terminating unloads Mesa's driver,
// and LeakSanitizer can then neither name nor suppress (.ci/lsan.supp) the allocations
// the driver keeps until exit; our own leaks are reported either way.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SPINDRIFT_KEEP_EGL_DISPLAY 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define SPINDRIFT_KEEP_EGL_DISPLAY 1
#endif

void release_display(EGLDisplay display) {
#ifndef SPINDRIFT_KEEP_EGL_DISPLAY
    if (--g_live_contexts == 0) eglTerminate(display);
#else
    (void)display;
    --g_live_contexts;
#endif
}

bool has_extension(const char* list, std::string_view name) {
    if (list == nullptr) return false;
    std::string_view rest(list);
    while (!rest.empty()) {
        const std::size_t space = rest.find(' ');
        if (rest.substr(0, space) == name) return true;
        if (space == std::string_view::npos) break;
        rest.remove_prefix(space + 1);
    }
    return false;
}

[[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("EGL: " + what + " (" + HeadlessContext::egl_error_name(eglGetError()) +
                             ")");
}

std::string gl_string(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text ? text : "(unknown)";
}

}  // namespace

const char* HeadlessContext::egl_error_name(int error) {
    switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return "unknown EGL error";
    }
}

HeadlessContext::HeadlessContext(Options options) : debug_(options.debug) {
    const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!has_extension(client_extensions, "EGL_MESA_platform_surfaceless") ||
        get_platform_display == nullptr)
        fail("no surfaceless platform (is Mesa's libegl-mesa0 installed?)");

    EGLDisplay display =
        get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY)
        fail("no surfaceless platform (is Mesa's libegl-mesa0 installed?)");

    std::lock_guard lock(g_display_mutex);
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) fail("cannot initialise the surfaceless display");
    ++g_live_contexts;  // from here on the destructor's cleanup applies
    display_ = display;
    try {
        const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
        for (std::string_view needed : {"EGL_KHR_no_config_context", "EGL_KHR_surfaceless_context"})
            if (!has_extension(extensions, needed))
                throw std::runtime_error("EGL: display lacks " + std::string(needed));
        if (!eglBindAPI(EGL_OPENGL_API)) fail("cannot bind the OpenGL API");

        const EGLint attributes[] = {
            EGL_CONTEXT_MAJOR_VERSION, 4,
            EGL_CONTEXT_MINOR_VERSION, 5,
            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
            EGL_CONTEXT_OPENGL_DEBUG, options.debug ? EGL_TRUE : EGL_FALSE,
            EGL_NONE};
        context_ = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
        if (context_ == EGL_NO_CONTEXT) fail("cannot create an OpenGL 4.5 core context");
        make_current();
    } catch (...) {
        // The destructor does not run for a constructor that throws.
        if (context_ != nullptr) eglDestroyContext(display, context_);
        release_display(display);
        throw;
    }
    renderer_ = gl_string(GL_RENDERER);
    version_ = gl_string(GL_VERSION);
}

HeadlessContext::~HeadlessContext() {
    std::lock_guard lock(g_display_mutex);
    if (eglGetCurrentContext() == context_)
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    release_display(display_);
}

void HeadlessContext::make_current() {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
        fail("cannot make the context current");
}

}  // namespace game
