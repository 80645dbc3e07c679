#include "effects/gl/Buffer.h"

#include <algorithm>
#include <stdexcept>

namespace effects::gl {

Buffer Buffer::create(std::string_view label, GLsizeiptr size_bytes, const void* data,
                      GLbitfield flags) {
    if (size_bytes <= 0)
        throw std::invalid_argument("buffer '" + std::string(label) +
                                    "': size must be positive, got " + std::to_string(size_bytes));
    Buffer buffer;
    GLuint name = 0;
    glCreateBuffers(1, &name);
    buffer.handle_.reset(name);
    glNamedBufferStorage(name, size_bytes, data, flags);
    label_object(GL_BUFFER, name, label);
    buffer.size_bytes_ = size_bytes;
    buffer.flags_ = flags;
    buffer.label_ = label;
    return buffer;
}

void Buffer::update(GLintptr offset_bytes, std::span<const std::byte> bytes) {
    if ((flags_ & GL_DYNAMIC_STORAGE_BIT) == 0)
        throw std::logic_error("buffer '" + label_ +
                               "': update() needs GL_DYNAMIC_STORAGE_BIT at creation");
    const auto count = static_cast<GLsizeiptr>(bytes.size());
    if (offset_bytes < 0 || offset_bytes > size_bytes_ || count > size_bytes_ - offset_bytes)
        throw std::out_of_range("buffer '" + label_ + "': update of " + std::to_string(count) +
                                " bytes at offset " + std::to_string(offset_bytes) +
                                " exceeds its size " + std::to_string(size_bytes_));
    if (count == 0) return;
    glNamedBufferSubData(id(), offset_bytes, count, bytes.data());
}

bool upload_growing(Buffer& buffer, std::string_view label, std::span<const std::byte> bytes) {
    const GLsizeiptr size = std::max<GLsizeiptr>(GLsizeiptr(bytes.size()), 16);
    const bool grow = buffer.id() == 0 || buffer.size() < size;
    if (grow) buffer = Buffer::create(label, std::max(size, 2 * buffer.size()));
    if (!bytes.empty()) buffer.update(0, bytes);
    return grow;
}

}  // namespace effects::gl
