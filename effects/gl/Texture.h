#pragma once
#include "effects/gl/Gl.h"
#include "effects/gl/Handle.h"

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace effects::gl {

// Immutable-storage texture (glTextureStorage*): 2D, 2D array or cube map.
// Pixel rows in uploads are in GL order: row 0 is the bottom of the image.
class Texture {
public:
    Texture() = default;

    // Sizes must be within the GL limits and levels within 1..full_mip_levels();
    // otherwise std::invalid_argument naming the label.
    static Texture create_2d(std::string_view label, GLenum internal_format, int width,
                             int height, int levels = 1);
    static Texture create_2d_array(std::string_view label, GLenum internal_format, int width,
                                   int height, int layers, int levels = 1);
    static Texture create_cube(std::string_view label, GLenum internal_format, int size,
                               int levels = 1);

    static int full_mip_levels(int width, int height);

    // Replaces a whole mip level of a 2D texture. The byte count must match
    // width x height of that level for `format`/`type`, rows tightly packed.
    void upload(GLenum format, GLenum type, std::span<const std::byte> pixels, int level = 0);
    // Replaces one layer of an array, or one face of a cube (0..5 = +X,-X,+Y,-Y,+Z,-Z).
    void upload_layer(int layer, GLenum format, GLenum type, std::span<const std::byte> pixels,
                      int level = 0);

    template <typename T>
    void upload(GLenum format, GLenum type, std::span<const T> pixels, int level = 0) {
        upload(format, type, std::as_bytes(pixels), level);
    }
    template <typename T>
    void upload_layer(int layer, GLenum format, GLenum type, std::span<const T> pixels,
                      int level = 0) {
        upload_layer(layer, format, type, std::as_bytes(pixels), level);
    }

    void generate_mipmaps();

    // Sampler state stored in the texture object.
    void set_filter(GLenum min_filter, GLenum mag_filter);
    void set_wrap(GLenum wrap);  // S, T and R alike
    void set_border_colour(const std::array<float, 4>& rgba);
    // Shadow maps: with compare on, a sampler*Shadow lookup returns the depth test result.
    void set_depth_compare(bool enabled, GLenum compare_func = GL_LEQUAL);

    void bind(GLuint unit) const { glBindTextureUnit(unit, id()); }
    // For compute/image load-store; binds all layers of arrays and cubes.
    void bind_image(GLuint unit, GLenum access, int level = 0) const;

    GLuint id() const { return handle_.get(); }
    GLenum target() const { return target_; }
    GLenum internal_format() const { return internal_format_; }
    int width() const { return width_; }
    int height() const { return height_; }
    int layers() const { return layers_; }  // 1 for 2D, 6 for a cube
    int levels() const { return levels_; }
    bool is_depth() const;
    bool has_stencil() const;
    const std::string& label() const { return label_; }

private:
    static Texture create(std::string_view label, GLenum target, GLenum internal_format,
                          int width, int height, int layers, int levels);
    void upload_region(int layer, GLenum format, GLenum type, std::span<const std::byte> pixels,
                       int level);

    Handle<TextureDeleter> handle_;
    GLenum target_ = 0;
    GLenum internal_format_ = 0;
    int width_ = 0;
    int height_ = 0;
    int layers_ = 0;
    int levels_ = 0;
    std::string label_;
};

}  // namespace effects::gl
