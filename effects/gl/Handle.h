#pragma once
#include "effects/gl/Gl.h"

#include <utility>

namespace effects::gl {

// Owns one GL object name. Deleter is a type with `static void destroy(GLuint)`.
// Move-only; the GL context must outlive every handle (destruction calls GL).
template <typename Deleter>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint name) : name_(name) {}
    ~Handle() { reset(); }

    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) reset(std::exchange(other.name_, 0));
        return *this;
    }

    GLuint get() const { return name_; }
    explicit operator bool() const { return name_ != 0; }

    // Gives up ownership without deleting.
    GLuint release() { return std::exchange(name_, 0); }

    // Deletes the owned object (if any) and takes `name` instead.
    void reset(GLuint name = 0) {
        if (name_ != 0) Deleter::destroy(name_);
        name_ = name;
    }

private:
    GLuint name_ = 0;
};

struct BufferDeleter {
    static void destroy(GLuint name) { glDeleteBuffers(1, &name); }
};
struct VertexArrayDeleter {
    static void destroy(GLuint name) { glDeleteVertexArrays(1, &name); }
};
struct TextureDeleter {
    static void destroy(GLuint name) { glDeleteTextures(1, &name); }
};
struct FramebufferDeleter {
    static void destroy(GLuint name) { glDeleteFramebuffers(1, &name); }
};
struct ProgramDeleter {
    static void destroy(GLuint name) { glDeleteProgram(name); }
};
struct ShaderDeleter {
    static void destroy(GLuint name) { glDeleteShader(name); }
};
struct QueryDeleter {
    static void destroy(GLuint name) { glDeleteQueries(1, &name); }
};

}  // namespace effects::gl
