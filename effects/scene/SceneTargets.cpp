#include "effects/scene/SceneTargets.h"

namespace effects {

void SceneTargets::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    ++generation_;
    colour_ = gl::Texture::create_2d("scene.colour", GL_RGBA16F, width, height);
    normal_ = gl::Texture::create_2d("scene.normal", GL_RGBA16F, width, height);
    depth_ = gl::Texture::create_2d("scene.depth", GL_DEPTH_COMPONENT32F, width, height);
    // Mips for the rain's out-of-focus reads; the filter set below reads level 0 only.
    colour_copy_ = gl::Texture::create_2d("scene.colour_copy", GL_RGBA16F, width, height,
                                          gl::Texture::full_mip_levels(width, height));
    depth_copy_ = gl::Texture::create_2d("scene.depth_copy", GL_DEPTH_COMPONENT32F, width, height);
    for (gl::Texture* t : {&colour_, &normal_, &depth_, &colour_copy_, &depth_copy_}) {
        t->set_filter(GL_LINEAR, GL_LINEAR);
        t->set_wrap(GL_CLAMP_TO_EDGE);
    }
    depth_copy_.set_filter(GL_NEAREST, GL_NEAREST);
    hdr_fbo_ = gl::Framebuffer::create("scene");
    hdr_fbo_.attach_colour(0, colour_);
    hdr_fbo_.attach_colour(1, normal_);
    hdr_fbo_.attach_depth(depth_);
    set_hdr_draw_buffers();
    hdr_fbo_.check_complete();
    copy_fbo_ = gl::Framebuffer::create("scene.copy");
    copy_fbo_.attach_colour(0, colour_copy_);
    copy_fbo_.attach_depth(depth_copy_);
    copy_fbo_.set_draw_buffers({0});
    copy_fbo_.check_complete();
    display_ = gl::Texture{};
    display_fbo_ = gl::Framebuffer{};
    antialiased_ = gl::Texture{};
    antialiased_fbo_ = gl::Framebuffer{};
    for (int i = 0; i < 2; ++i) {
        history_[i] = gl::Texture{};
        history_fbo_[i] = gl::Framebuffer{};
    }
}

void SceneTargets::write_normals(bool on) {
    writes_normals_ = on;
    if (hdr_fbo_.id() != 0) set_hdr_draw_buffers();
}

void SceneTargets::set_hdr_draw_buffers() {
    if (writes_normals_)
        hdr_fbo_.set_draw_buffers({0, 1});
    else
        hdr_fbo_.set_draw_buffers({0});
}

const gl::Framebuffer& SceneTargets::display_fbo() {
    if (display_.id() == 0) {
        display_ = gl::Texture::create_2d("scene.display", GL_RGBA8, width_, height_);
        display_.set_filter(GL_LINEAR, GL_LINEAR);
        display_.set_wrap(GL_CLAMP_TO_EDGE);
        display_fbo_ = gl::Framebuffer::create("scene.display");
        display_fbo_.attach_colour(0, display_);
        display_fbo_.check_complete();
    }
    return display_fbo_;
}

void SceneTargets::start_history_frame() {
    current_history_ = 1 - current_history_;
    for (int i = 0; i < 2; ++i) {
        if (history_[i].id() != 0) continue;
        history_[i] = gl::Texture::create_2d("scene.history", GL_RGBA8, width_, height_);
        history_[i].set_filter(GL_LINEAR, GL_LINEAR);
        history_[i].set_wrap(GL_CLAMP_TO_EDGE);
        history_fbo_[i] = gl::Framebuffer::create("scene.history");
        history_fbo_[i].attach_colour(0, history_[i]);
        history_fbo_[i].check_complete();
    }
}

const gl::Framebuffer& SceneTargets::antialiased_fbo() {
    if (antialiased_.id() == 0) {
        antialiased_ = gl::Texture::create_2d("scene.antialiased", GL_RGBA8, width_, height_);
        antialiased_.set_filter(GL_NEAREST, GL_NEAREST);
        antialiased_.set_wrap(GL_CLAMP_TO_EDGE);
        antialiased_fbo_ = gl::Framebuffer::create("scene.antialiased");
        antialiased_fbo_.attach_colour(0, antialiased_);
        antialiased_fbo_.check_complete();
    }
    return antialiased_fbo_;
}

void SceneTargets::copy_scene() {
    glNamedFramebufferReadBuffer(hdr_fbo_.id(), GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(hdr_fbo_.id(), copy_fbo_.id(), 0, 0, width_, height_, 0, 0, width_, height_,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBlitNamedFramebuffer(hdr_fbo_.id(), copy_fbo_.id(), 0, 0, width_, height_, 0, 0, width_, height_,
                           GL_DEPTH_BUFFER_BIT, GL_NEAREST);
}

void SceneTargets::refresh_colour_copy(glm::ivec4 rect) {
    if (rect.z <= rect.x || rect.w <= rect.y) return;
    glCopyImageSubData(colour_.id(), GL_TEXTURE_2D, 0, rect.x, rect.y, 0, colour_copy_.id(), GL_TEXTURE_2D, 0, rect.x,
                       rect.y, 0, rect.z - rect.x, rect.w - rect.y, 1);
}

void SceneTargets::refresh_colour_copy_with_mips() {
    refresh_colour_copy({0, 0, width_, height_});
    colour_copy_.generate_mipmaps();
}

}  // namespace effects
