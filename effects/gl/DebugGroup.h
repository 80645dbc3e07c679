#pragma once
#include "effects/gl/Gl.h"

#include <algorithm>
#include <string_view>

namespace effects::gl {

// Names a span of GL commands (a pass) for RenderDoc and debug output:
// pushes a debug group now, pops it at scope exit.
class DebugGroup {
public:
    explicit DebugGroup(std::string_view name) {
        // A name of GL_MAX_DEBUG_MESSAGE_LENGTH (4096 on Mesa) or more is a GL error:
        // cap it well below.
        const auto length = static_cast<GLsizei>(std::min<std::size_t>(name.size(), 255));
        glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, length, name.data());
    }
    ~DebugGroup() { glPopDebugGroup(); }

    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

}  // namespace effects::gl
