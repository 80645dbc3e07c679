#pragma once
// OpenGL 4.5 core entry points. No loader on Linux: libOpenGL (glvnd) exports them
// and dispatches to the current context's driver.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>

#include <algorithm>
#include <string_view>

namespace effects::gl {

// Names a GL object so RenderDoc and debug messages show what it is.
// GL_MAX_LABEL_LENGTH is at least 256, so longer labels are cut to stay valid.
inline void label_object(GLenum identifier, GLuint name, std::string_view label) {
    if (name == 0 || label.empty()) return;
    const auto length = static_cast<GLsizei>(std::min<std::size_t>(label.size(), 255));
    glObjectLabel(identifier, name, length, label.data());
}

}  // namespace effects::gl
