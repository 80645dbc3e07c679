#include "effects/gl/VertexArray.h"

#include "effects/gl/Buffer.h"

namespace effects::gl {

VertexArray VertexArray::create(std::string_view label) {
    VertexArray vao;
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    vao.handle_.reset(name);
    label_object(GL_VERTEX_ARRAY, name, label);
    return vao;
}

void VertexArray::attribute(GLuint location, GLuint binding, GLint components, GLenum type,
                            GLuint relative_offset_bytes, bool normalized) {
    glEnableVertexArrayAttrib(id(), location);
    glVertexArrayAttribFormat(id(), location, components, type, normalized ? GL_TRUE : GL_FALSE,
                              relative_offset_bytes);
    glVertexArrayAttribBinding(id(), location, binding);
}

void VertexArray::attribute_integer(GLuint location, GLuint binding, GLint components,
                                    GLenum type, GLuint relative_offset_bytes) {
    glEnableVertexArrayAttrib(id(), location);
    glVertexArrayAttribIFormat(id(), location, components, type, relative_offset_bytes);
    glVertexArrayAttribBinding(id(), location, binding);
}

void VertexArray::vertex_buffer(GLuint binding, const Buffer& buffer, GLintptr offset_bytes,
                                GLsizei stride_bytes) {
    glVertexArrayVertexBuffer(id(), binding, buffer.id(), offset_bytes, stride_bytes);
}

void VertexArray::binding_divisor(GLuint binding, GLuint divisor) {
    glVertexArrayBindingDivisor(id(), binding, divisor);
}

void VertexArray::element_buffer(const Buffer& buffer) {
    glVertexArrayElementBuffer(id(), buffer.id());
}

}  // namespace effects::gl
