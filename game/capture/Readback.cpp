#include "game/capture/Readback.h"

#include "effects/gl/Framebuffer.h"

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

namespace game {
namespace {

constexpr int kMaxReadbackSide = 16384;

void check_size(const char* what, int width, int height) {
    if (width < 1 || height < 1 || width > kMaxReadbackSide || height > kMaxReadbackSide)
        throw std::invalid_argument(std::string(what) + ": size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " outside 1.." +
                                    std::to_string(kMaxReadbackSide));
}

// GL rows are bottom-up; images are top-down.
template <typename T>
void flip_rows(std::vector<T>& pixels, std::size_t row_values, int height) {
    std::vector<T> row(row_values);
    for (int y = 0; y < height / 2; ++y) {
        T* top = &pixels[std::size_t(y) * row_values];
        T* bottom = &pixels[std::size_t(height - 1 - y) * row_values];
        std::memcpy(row.data(), top, row_values * sizeof(T));
        std::memcpy(top, bottom, row_values * sizeof(T));
        std::memcpy(bottom, row.data(), row_values * sizeof(T));
    }
}

// Binds `framebuffer` for reading with tight packing and no pack buffer; restores
// the previous state when done.
class ReadState {
public:
    ReadState(const char* what, GLuint framebuffer, GLenum attachment, bool colour) {
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &old_framebuffer_);
        glGetIntegerv(GL_PACK_ALIGNMENT, &old_alignment_);
        glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &old_pack_buffer_);
        while (glGetError() != GL_NO_ERROR) {
        }  // earlier errors are not ours to report
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
        if (framebuffer != 0) {
            if (colour) {
                glGetIntegerv(GL_READ_BUFFER, &old_read_buffer_);
                glNamedFramebufferReadBuffer(framebuffer, attachment);
                restore_read_buffer_ = framebuffer;
            }
            const GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_READ_FRAMEBUFFER);
            if (status != GL_FRAMEBUFFER_COMPLETE) {
                restore();
                throw std::runtime_error(std::string(what) + ": framebuffer " +
                                         std::to_string(framebuffer) +
                                         " is not complete for reading: " +
                                         effects::gl::Framebuffer::status_name(status));
            }
        }
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    }
    ~ReadState() { restore(); }
    ReadState(const ReadState&) = delete;
    ReadState& operator=(const ReadState&) = delete;

    static void check_error(const char* what) {
        if (const GLenum error = glGetError(); error != GL_NO_ERROR)
            throw std::runtime_error(std::string(what) + ": glReadnPixels failed with GL error 0x" +
                                     hex(error));
    }

private:
    static std::string hex(GLenum value) {
        char text[16];
        std::snprintf(text, sizeof text, "%04X", value);
        return text;
    }
    void restore() {
        if (restored_) return;
        restored_ = true;
        if (restore_read_buffer_ != 0)
            glNamedFramebufferReadBuffer(restore_read_buffer_, static_cast<GLenum>(old_read_buffer_));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(old_framebuffer_));
        glPixelStorei(GL_PACK_ALIGNMENT, old_alignment_);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(old_pack_buffer_));
    }

    GLint old_framebuffer_ = 0, old_alignment_ = 4, old_pack_buffer_ = 0, old_read_buffer_ = 0;
    GLuint restore_read_buffer_ = 0;
    bool restored_ = false;
};

template <typename T>
std::vector<T> read_pixels(const char* what, GLuint framebuffer, GLenum attachment, bool colour,
                           int width, int height, GLenum format, GLenum type,
                           std::size_t values_per_pixel) {
    check_size(what, width, height);
    const std::size_t row_values = std::size_t(width) * values_per_pixel;
    std::vector<T> pixels(row_values * std::size_t(height));
    ReadState state(what, framebuffer, attachment, colour);
    glReadnPixels(0, 0, width, height, format, type,
                  static_cast<GLsizei>(pixels.size() * sizeof(T)), pixels.data());
    ReadState::check_error(what);
    flip_rows(pixels, row_values, height);
    return pixels;
}

}  // namespace

ImageRGBA8 read_framebuffer_rgba8(GLuint framebuffer, int width, int height, GLenum attachment) {
    return {width, height,
            read_pixels<std::uint8_t>("read_framebuffer_rgba8", framebuffer, attachment, true,
                                      width, height, GL_RGBA, GL_UNSIGNED_BYTE, 4)};
}

ImageRGBA32F read_framebuffer_rgba32f(GLuint framebuffer, GLenum attachment, int width,
                                      int height) {
    return {width, height,
            read_pixels<float>("read_framebuffer_rgba32f", framebuffer, attachment, true, width,
                               height, GL_RGBA, GL_FLOAT, 4)};
}

std::vector<float> read_depth(GLuint framebuffer, int width, int height) {
    return read_pixels<float>("read_depth", framebuffer, GL_NONE, false, width, height,
                              GL_DEPTH_COMPONENT, GL_FLOAT, 1);
}

}  // namespace game
