#pragma once
#include "effects/gl/Gl.h"
#include "effects/gl/Handle.h"

#include <string_view>

namespace effects::gl {

class Buffer;

// Vertex array object set up with separate attribute formats (4.3 vertex binding):
// attributes read from binding points, buffers attach to binding points.
class VertexArray {
public:
    VertexArray() = default;
    static VertexArray create(std::string_view label);

    // Float attribute at `location` with `components` values of `type` (e.g. GL_FLOAT,
    // or GL_UNSIGNED_BYTE with normalized = true), read from binding point `binding`.
    void attribute(GLuint location, GLuint binding, GLint components, GLenum type,
                   GLuint relative_offset_bytes, bool normalized = false);
    // Integer attribute (ivec/uvec in the shader).
    void attribute_integer(GLuint location, GLuint binding, GLint components, GLenum type,
                           GLuint relative_offset_bytes);

    void vertex_buffer(GLuint binding, const Buffer& buffer, GLintptr offset_bytes,
                       GLsizei stride_bytes);
    // 0 = per vertex, n = advance once every n instances.
    void binding_divisor(GLuint binding, GLuint divisor);
    void element_buffer(const Buffer& buffer);

    void bind() const { glBindVertexArray(id()); }
    GLuint id() const { return handle_.get(); }

private:
    Handle<VertexArrayDeleter> handle_;
};

}  // namespace effects::gl
