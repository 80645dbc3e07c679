#pragma once
// The frame's shared render targets: HDR colour, world normals and depth that the
// opaque passes write, a copy of colour and depth that the water refracts (the fluid
// and the rain keep copies of their own), and the tone-mapped display image.
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Texture.h"

namespace effects {

class SceneTargets {
public:
    void resize(int width, int height);
    // Copies colour and depth so that later passes can sample them while drawing.
    void copy_scene();

    int width() const { return width_; }
    int height() const { return height_; }
    const gl::Framebuffer& scene() const { return scene_fbo_; }
    const gl::Texture& colour() const { return colour_; }
    const gl::Texture& normal() const { return normal_; }
    const gl::Texture& depth() const { return depth_; }
    const gl::Texture& colour_copy() const { return colour_copy_; }
    const gl::Texture& depth_copy() const { return depth_copy_; }
    // The tone-mapped frame at the scene's size, when the output is larger (render scale
    // below 1): the upscale reads it. Made on first use.
    const gl::Framebuffer& display_fbo();
    const gl::Texture& display() const { return display_; }

private:
    int width_ = 0, height_ = 0;
    gl::Texture colour_, normal_, depth_, colour_copy_, depth_copy_, display_;
    gl::Framebuffer scene_fbo_, copy_fbo_, display_fbo_;
};

}  // namespace effects
