#pragma once
#include "effects/gl/Gl.h"
#include "effects/gl/Handle.h"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace effects::gl {

// Immutable-storage GL buffer (glNamedBufferStorage). Contents can change through
// update() only when created with GL_DYNAMIC_STORAGE_BIT (the default).
class Buffer {
public:
    Buffer() = default;

    // `data` may be null (uninitialised storage). Throws std::invalid_argument for
    // size_bytes <= 0.
    static Buffer create(std::string_view label, GLsizeiptr size_bytes, const void* data = nullptr,
                         GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);

    template <typename T>
    static Buffer create(std::string_view label, std::span<const T> items,
                         GLbitfield flags = GL_DYNAMIC_STORAGE_BIT) {
        return create(label, static_cast<GLsizeiptr>(items.size_bytes()), items.data(), flags);
    }

    // Writes bytes at offset_bytes. Throws std::out_of_range past the end and
    // std::logic_error if the buffer was not created dynamic.
    void update(GLintptr offset_bytes, std::span<const std::byte> bytes);

    template <typename T>
    void update(GLintptr offset_bytes, std::span<const T> items) {
        update(offset_bytes, std::as_bytes(items));
    }

    GLuint id() const { return handle_.get(); }
    GLsizeiptr size() const { return size_bytes_; }
    const std::string& label() const { return label_; }

private:
    Handle<BufferDeleter> handle_;
    GLsizeiptr size_bytes_ = 0;
    GLbitfield flags_ = 0;
    std::string label_;
};

// Writes bytes at the start of `buffer`, first recreating it (at least doubled, and of
// 16 bytes or more so an empty list still binds) when it is too small. Returns whether
// it was recreated: whatever referred to the old buffer must be pointed at the new one.
bool upload_growing(Buffer& buffer, std::string_view label, std::span<const std::byte> bytes);

}  // namespace effects::gl
