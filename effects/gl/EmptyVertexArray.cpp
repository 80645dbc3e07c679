#include "effects/gl/EmptyVertexArray.h"

#include "effects/gl/Gl.h"

namespace effects::gl {

void bind_empty_vertex_array() {
    // One per thread's context; the program uses one GL context per thread at most.
    thread_local GLuint vao = 0;
    if (!glIsVertexArray(vao)) {
        glCreateVertexArrays(1, &vao);
        glObjectLabel(GL_VERTEX_ARRAY, vao, -1, "empty");
    }
    glBindVertexArray(vao);
}

}  // namespace effects::gl
