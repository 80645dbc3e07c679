#pragma once
// The frame's shared render targets: HDR colour, depth and (when asked) world normals
// that the opaque passes write, one copy of colour and depth that every refracting pass
// reads (the water as the scene_copy pass makes it; the fluid and the rain bring its
// colour up to date first), the tone-mapped display image and its anti-aliased copy.
#include <cstdint>

#include <glm/vec4.hpp>

#include "effects/gl/Framebuffer.h"
#include "effects/gl/Texture.h"

namespace effects {

class SceneTargets {
public:
    void resize(int width, int height);
    // Copies colour and depth so that later passes can sample them while drawing.
    void copy_scene();
    // Copies the colour again inside `rect` (x0, y0, x1, y1 in pixels, x1/y1 exclusive,
    // within the targets); the rest of the copy stays as it was.
    void refresh_colour_copy(glm::ivec4 rect);
    // Copies the whole colour again and makes the copy's mips from it, for blurred reads
    // (through a sampler with a mipmap filter: the copy's own filter reads level 0 only).
    void refresh_colour_copy_with_mips();
    // Goes up each time resize() re-creates the targets: a framebuffer a pass builds over
    // them is rebuilt when the generation it was built for differs (a size can come back,
    // and a texture name can be reused, while the pass was not drawing).
    uint64_t generation() const { return generation_; }
    // Whether the HDR framebuffer draws world normals (its second draw buffer): only an
    // EXR capture reads them, so they are left out unless asked for (off at first).
    // The passes drawing into it compile their normals output in or out to match.
    void write_normals(bool on);
    bool writes_normals() const { return writes_normals_; }

    int width() const { return width_; }
    int height() const { return height_; }
    // The 3D scene's HDR framebuffer: colour (0), normals (1), depth.
    const gl::Framebuffer& hdr() const { return hdr_fbo_; }
    const gl::Texture& colour() const { return colour_; }
    const gl::Texture& normal() const { return normal_; }
    const gl::Texture& depth() const { return depth_; }
    const gl::Texture& colour_copy() const { return colour_copy_; }
    const gl::Texture& depth_copy() const { return depth_copy_; }
    // The tone-mapped frame at the scene's size, when the output is larger (render scale
    // below 1) or anti-aliasing reads it; bilinear for the anti-aliasing's taps. Made on
    // first use.
    const gl::Framebuffer& display_fbo();
    const gl::Texture& display() const { return display_; }
    // The display image anti-aliased, when the upscale still has to bring it to the
    // output. Made on first use.
    const gl::Framebuffer& antialiased_fbo();
    const gl::Texture& antialiased() const { return antialiased_; }
    // Temporal upsampling's two resolved images at the scene's size (TemporalPass):
    // start_history_frame() makes last frame's the one read (previous_history()) and the
    // other the one written (history_fbo(), history()). Made on first use, bilinear.
    void start_history_frame();
    const gl::Framebuffer& history_fbo() const { return history_fbo_[current_history_]; }
    const gl::Texture& history() const { return history_[current_history_]; }
    const gl::Texture& previous_history() const { return history_[1 - current_history_]; }

private:
    void set_hdr_draw_buffers();

    int width_ = 0, height_ = 0;
    uint64_t generation_ = 0;
    bool writes_normals_ = false;
    gl::Texture colour_, normal_, depth_, colour_copy_, depth_copy_, display_, antialiased_;
    gl::Framebuffer hdr_fbo_, copy_fbo_, display_fbo_, antialiased_fbo_;
    gl::Texture history_[2];
    gl::Framebuffer history_fbo_[2];
    int current_history_ = 0;
};

}  // namespace effects
