#include "effects/gl/Framebuffer.h"

#include "effects/gl/Texture.h"

#include <algorithm>
#include <stdexcept>

namespace effects::gl {
namespace {

void check_colour_index(const std::string& label, int index) {
    GLint max_attachments = 0;
    glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &max_attachments);
    if (index < 0 || index >= max_attachments)
        throw std::out_of_range("framebuffer '" + label + "': colour attachment " +
                                std::to_string(index) + " outside 0.." +
                                std::to_string(max_attachments - 1));
}

void check_layer(const std::string& label, const Texture& texture, int layer) {
    if (texture.target() == GL_TEXTURE_2D || layer < 0 || layer >= texture.layers())
        throw std::out_of_range("framebuffer '" + label + "': layer " + std::to_string(layer) +
                                " of texture '" + texture.label() + "' (" +
                                std::to_string(texture.layers()) + " layers, " +
                                (texture.target() == GL_TEXTURE_2D ? "2D" : "layered") + ")");
}

void check_depth(const std::string& label, const Texture& texture) {
    if (!texture.is_depth())
        throw std::invalid_argument("framebuffer '" + label + "': texture '" + texture.label() +
                                    "' attached as depth has no depth format");
}

}  // namespace

Framebuffer Framebuffer::create(std::string_view label) {
    Framebuffer fbo;
    GLuint name = 0;
    glCreateFramebuffers(1, &name);
    fbo.handle_.reset(name);
    label_object(GL_FRAMEBUFFER, name, label);
    fbo.label_ = label;
    // No colour until something is attached: a depth-only target is then complete.
    glNamedFramebufferDrawBuffer(name, GL_NONE);
    glNamedFramebufferReadBuffer(name, GL_NONE);
    return fbo;
}

void Framebuffer::attach_colour(int index, const Texture& texture, int level) {
    check_colour_index(label_, index);
    glNamedFramebufferTexture(id(), GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(index),
                              texture.id(), level);
    note_colour_attachment(index);
}

void Framebuffer::attach_colour_layer(int index, const Texture& texture, int layer, int level) {
    check_colour_index(label_, index);
    check_layer(label_, texture, layer);
    glNamedFramebufferTextureLayer(id(), GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(index),
                                   texture.id(), level, layer);
    note_colour_attachment(index);
}

void Framebuffer::attach_depth(const Texture& texture, int level) {
    check_depth(label_, texture);
    glNamedFramebufferTexture(id(),
                              texture.has_stencil() ? GL_DEPTH_STENCIL_ATTACHMENT
                                                    : GL_DEPTH_ATTACHMENT,
                              texture.id(), level);
}

void Framebuffer::attach_depth_layer(const Texture& texture, int layer, int level) {
    check_depth(label_, texture);
    check_layer(label_, texture, layer);
    glNamedFramebufferTextureLayer(id(),
                                   texture.has_stencil() ? GL_DEPTH_STENCIL_ATTACHMENT
                                                         : GL_DEPTH_ATTACHMENT,
                                   texture.id(), level, layer);
}

void Framebuffer::note_colour_attachment(int index) {
    if (std::find(colour_indices_.begin(), colour_indices_.end(), index) == colour_indices_.end()) {
        colour_indices_.push_back(index);
        std::sort(colour_indices_.begin(), colour_indices_.end());
    }
    if (!explicit_draw_buffers_) {
        std::vector<GLenum> buffers;
        for (int i : colour_indices_) {
            // Output location n writes buffers[n]: keep location == attachment index.
            while (static_cast<int>(buffers.size()) < i) buffers.push_back(GL_NONE);
            buffers.push_back(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i));
        }
        glNamedFramebufferDrawBuffers(id(), static_cast<GLsizei>(buffers.size()), buffers.data());
    }
    if (index == colour_indices_.front())
        glNamedFramebufferReadBuffer(id(), GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(index));
}

void Framebuffer::set_draw_buffers(const std::vector<int>& colour_indices) {
    std::vector<GLenum> buffers;
    for (int i : colour_indices) {
        check_colour_index(label_, i);
        buffers.push_back(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i));
    }
    if (buffers.empty())
        glNamedFramebufferDrawBuffer(id(), GL_NONE);
    else
        glNamedFramebufferDrawBuffers(id(), static_cast<GLsizei>(buffers.size()), buffers.data());
    explicit_draw_buffers_ = true;
}

void Framebuffer::check_complete() const {
    const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("framebuffer '" + label_ + "' incomplete: " +
                                 status_name(status));
}

const char* Framebuffer::status_name(GLenum status) {
    switch (status) {
    case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
        return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    case 0: return "error while checking (invalid framebuffer?)";
    default: return "unknown framebuffer status";
    }
}

}  // namespace effects::gl
