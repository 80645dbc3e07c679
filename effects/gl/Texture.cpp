#include "effects/gl/Texture.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <stdexcept>

namespace effects::gl {
namespace {

int max_integer(GLenum limit) {
    GLint value = 0;
    glGetIntegerv(limit, &value);
    return value;
}

int components_of(GLenum format) {
    switch (format) {
    case GL_RED: case GL_RED_INTEGER: case GL_DEPTH_COMPONENT: case GL_STENCIL_INDEX: return 1;
    case GL_RG: case GL_RG_INTEGER: case GL_DEPTH_STENCIL: return 2;
    case GL_RGB: case GL_BGR: case GL_RGB_INTEGER: return 3;
    case GL_RGBA: case GL_BGRA: case GL_RGBA_INTEGER: return 4;
    default: return 0;
    }
}

int bytes_per_component(GLenum type) {
    switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: case GL_HALF_FLOAT: return 2;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: return 4;
    default: return 0;
    }
}

// Bytes per pixel of a client format/type pair; packed types hold the whole pixel.
std::size_t bytes_per_pixel(GLenum format, GLenum type) {
    if (type == GL_UNSIGNED_INT_24_8 || type == GL_UNSIGNED_INT_10F_11F_11F_REV ||
        type == GL_UNSIGNED_INT_2_10_10_10_REV)
        return 4;
    return static_cast<std::size_t>(components_of(format) * bytes_per_component(type));
}

std::string hex(GLenum value) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%04X", value);
    return text;
}

std::string dims(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

int Texture::full_mip_levels(int width, int height) {
    const int largest = std::max(std::max(width, height), 1);
    return std::bit_width(static_cast<unsigned>(largest));
}

Texture Texture::create(std::string_view label, GLenum target, GLenum internal_format,
                        int width, int height, int layers, int levels) {
    const std::string where = "texture '" + std::string(label) + "'";
    const int max_size = max_integer(target == GL_TEXTURE_CUBE_MAP ? GL_MAX_CUBE_MAP_TEXTURE_SIZE
                                                                   : GL_MAX_TEXTURE_SIZE);
    if (width < 1 || height < 1 || width > max_size || height > max_size)
        throw std::invalid_argument(where + ": size " + dims(width, height) +
                                    " outside 1.." + std::to_string(max_size));
    if (target == GL_TEXTURE_2D_ARRAY &&
        (layers < 1 || layers > max_integer(GL_MAX_ARRAY_TEXTURE_LAYERS)))
        throw std::invalid_argument(where + ": " + std::to_string(layers) +
                                    " layers outside 1.." +
                                    std::to_string(max_integer(GL_MAX_ARRAY_TEXTURE_LAYERS)));
    if (levels < 1 || levels > full_mip_levels(width, height))
        throw std::invalid_argument(where + ": " + std::to_string(levels) + " mip levels for " +
                                    dims(width, height) + ", at most " +
                                    std::to_string(full_mip_levels(width, height)));

    Texture texture;
    GLuint name = 0;
    glCreateTextures(target, 1, &name);
    texture.handle_.reset(name);
    if (target == GL_TEXTURE_2D_ARRAY)
        glTextureStorage3D(name, levels, internal_format, width, height, layers);
    else
        glTextureStorage2D(name, levels, internal_format, width, height);
    // An unknown internal format leaves the texture without storage: say so now,
    // not at the first draw.
    GLint immutable = 0;
    glGetTextureParameteriv(name, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
    if (!immutable)
        throw std::invalid_argument(where + ": storage not created (internal format " +
                                    hex(internal_format) + " not accepted)");
    label_object(GL_TEXTURE, name, label);

    texture.target_ = target;
    texture.internal_format_ = internal_format;
    texture.width_ = width;
    texture.height_ = height;
    texture.layers_ = target == GL_TEXTURE_CUBE_MAP ? 6 : layers;
    texture.levels_ = levels;
    texture.label_ = label;
    // Sensible defaults: no mips sampled unless there are some, clamp at edges.
    texture.set_filter(levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
    texture.set_wrap(GL_CLAMP_TO_EDGE);
    return texture;
}

Texture Texture::create_2d(std::string_view label, GLenum internal_format, int width,
                           int height, int levels) {
    return create(label, GL_TEXTURE_2D, internal_format, width, height, 1, levels);
}

Texture Texture::create_2d_array(std::string_view label, GLenum internal_format, int width,
                                 int height, int layers, int levels) {
    return create(label, GL_TEXTURE_2D_ARRAY, internal_format, width, height, layers, levels);
}

Texture Texture::create_cube(std::string_view label, GLenum internal_format, int size,
                             int levels) {
    return create(label, GL_TEXTURE_CUBE_MAP, internal_format, size, size, 1, levels);
}

void Texture::upload(GLenum format, GLenum type, std::span<const std::byte> pixels, int level) {
    if (target_ != GL_TEXTURE_2D)
        throw std::logic_error("texture '" + label_ + "': upload() is for 2D textures; "
                               "use upload_layer() for arrays and cube maps");
    upload_region(0, format, type, pixels, level);
}

void Texture::upload_layer(int layer, GLenum format, GLenum type,
                           std::span<const std::byte> pixels, int level) {
    if (target_ == GL_TEXTURE_2D)
        throw std::logic_error("texture '" + label_ + "': upload_layer() on a 2D texture");
    if (layer < 0 || layer >= layers_)
        throw std::out_of_range("texture '" + label_ + "': layer " + std::to_string(layer) +
                                " outside 0.." + std::to_string(layers_ - 1));
    upload_region(layer, format, type, pixels, level);
}

void Texture::upload_region(int layer, GLenum format, GLenum type,
                            std::span<const std::byte> pixels, int level) {
    const std::string where = "texture '" + label_ + "'";
    if (level < 0 || level >= levels_)
        throw std::out_of_range(where + ": mip level " + std::to_string(level) + " outside 0.." +
                                std::to_string(levels_ - 1));
    const std::size_t pixel_bytes = bytes_per_pixel(format, type);
    if (pixel_bytes == 0)
        throw std::invalid_argument(where + ": unsupported upload format/type pair");
    const int w = std::max(width_ >> level, 1);
    const int h = std::max(height_ >> level, 1);
    const std::size_t expected = pixel_bytes * static_cast<std::size_t>(w) * h;
    if (pixels.size() != expected)
        throw std::invalid_argument(where + ": upload of " + std::to_string(pixels.size()) +
                                    " bytes, level " + std::to_string(level) + " (" + dims(w, h) +
                                    ") needs " + std::to_string(expected));

    // Rows are tightly packed; restore the caller's alignment afterwards.
    GLint old_alignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &old_alignment);
    GLint old_unpack_buffer = 0;
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &old_unpack_buffer);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    if (target_ == GL_TEXTURE_2D)
        glTextureSubImage2D(id(), level, 0, 0, w, h, format, type, pixels.data());
    else  // DSA addresses array layers and cube faces alike as z
        glTextureSubImage3D(id(), level, 0, 0, layer, w, h, 1, format, type, pixels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, old_alignment);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(old_unpack_buffer));
}

void Texture::generate_mipmaps() { glGenerateTextureMipmap(id()); }

void Texture::set_filter(GLenum min_filter, GLenum mag_filter) {
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min_filter));
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(mag_filter));
}

void Texture::set_wrap(GLenum wrap) {
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_R, static_cast<GLint>(wrap));
}

void Texture::set_border_colour(const std::array<float, 4>& rgba) {
    glTextureParameterfv(id(), GL_TEXTURE_BORDER_COLOR, rgba.data());
}

void Texture::set_depth_compare(bool enabled, GLenum compare_func) {
    glTextureParameteri(id(), GL_TEXTURE_COMPARE_MODE,
                        enabled ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    glTextureParameteri(id(), GL_TEXTURE_COMPARE_FUNC, static_cast<GLint>(compare_func));
}

void Texture::bind_image(GLuint unit, GLenum access, int level) const {
    const GLboolean layered = target_ == GL_TEXTURE_2D ? GL_FALSE : GL_TRUE;
    glBindImageTexture(unit, id(), level, layered, 0, access, internal_format_);
}

bool Texture::is_depth() const {
    switch (internal_format_) {
    case GL_DEPTH_COMPONENT16: case GL_DEPTH_COMPONENT24: case GL_DEPTH_COMPONENT32:
    case GL_DEPTH_COMPONENT32F: case GL_DEPTH24_STENCIL8: case GL_DEPTH32F_STENCIL8:
        return true;
    default:
        return false;
    }
}

bool Texture::has_stencil() const {
    return internal_format_ == GL_DEPTH24_STENCIL8 || internal_format_ == GL_DEPTH32F_STENCIL8;
}

}  // namespace effects::gl
