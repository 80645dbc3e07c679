#include "effects/gl/DebugOutput.h"

#include <iostream>
#include <string_view>

namespace effects::gl {
namespace {

const char* source_name(GLenum source) {
    switch (source) {
    case GL_DEBUG_SOURCE_API: return "api";
    case GL_DEBUG_SOURCE_WINDOW_SYSTEM: return "window system";
    case GL_DEBUG_SOURCE_SHADER_COMPILER: return "shader compiler";
    case GL_DEBUG_SOURCE_THIRD_PARTY: return "third party";
    case GL_DEBUG_SOURCE_APPLICATION: return "application";
    default: return "other";
    }
}

const char* type_name(GLenum type) {
    switch (type) {
    case GL_DEBUG_TYPE_ERROR: return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY: return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
    default: return "other";
    }
}

}  // namespace

DebugOutput::DebugOutput() : DebugOutput(std::cerr) {}

DebugOutput::DebugOutput(std::ostream& sink) : sink_(sink) {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    // Only high and medium reach the callback: low and notifications (which include
    // every debug group push) would drown the useful ones.
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_FALSE);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_HIGH, 0, nullptr, GL_TRUE);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_MEDIUM, 0, nullptr,
                          GL_TRUE);
    glDebugMessageCallback(&DebugOutput::on_message, this);
}

DebugOutput::~DebugOutput() {
    glDebugMessageCallback(nullptr, nullptr);
    glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
}

void APIENTRY DebugOutput::on_message(GLenum source, GLenum type, GLuint id, GLenum severity,
                                        GLsizei length, const GLchar* message,
                                        const void* user) {
    // The pointer was `this` at install time; GL hands it back as const.
    auto* self = static_cast<DebugOutput*>(const_cast<void*>(user));
    self->handle(source, type, id, severity, length, message);
}

void DebugOutput::handle(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                         const GLchar* message) {
    if (severity != GL_DEBUG_SEVERITY_HIGH && severity != GL_DEBUG_SEVERITY_MEDIUM) return;
    const std::string_view text = length < 0 ? std::string_view(message)
                                             : std::string_view(message, static_cast<std::size_t>(length));
    std::lock_guard lock(mutex_);
    auto& texts = seen_[MessageId(source, type, id)];
    if (texts.contains(text) || texts.size() > kMaxTextsPerId) {
        ++suppressed_;
        return;
    }
    texts.emplace(text);
    if (texts.size() > kMaxTextsPerId) {
        sink_ << "GL: more messages with id " << id << " will not be printed\n";
        sink_.flush();
        return;
    }
    ++printed_;
    sink_ << "GL " << (severity == GL_DEBUG_SEVERITY_HIGH ? "HIGH" : "medium") << ' '
          << type_name(type) << " (" << source_name(source) << ", id " << id << "): " << text
          << (text.ends_with('\n') ? "" : "\n");
    sink_.flush();
}

std::size_t DebugOutput::printed() const {
    std::lock_guard lock(mutex_);
    return printed_;
}

std::size_t DebugOutput::suppressed() const {
    std::lock_guard lock(mutex_);
    return suppressed_;
}

}  // namespace effects::gl
