#pragma once
#include "effects/gl/Gl.h"
#include "effects/gl/Handle.h"

#include <string>
#include <string_view>
#include <vector>

namespace effects::gl {

class Texture;

// Framebuffer object with texture attachments. Attaching colour attachments makes
// them the draw buffers (in attachment order) unless set_draw_buffers() says otherwise.
class Framebuffer {
public:
    Framebuffer() = default;
    static Framebuffer create(std::string_view label);

    void attach_colour(int index, const Texture& texture, int level = 0);
    // One layer of an array texture or one face of a cube map.
    void attach_colour_layer(int index, const Texture& texture, int layer, int level = 0);
    // Depth, or depth+stencil for a depth-stencil format.
    void attach_depth(const Texture& texture, int level = 0);
    void attach_depth_layer(const Texture& texture, int layer, int level = 0);

    // Colour attachment indices to draw into, in fragment output order; an empty
    // list draws no colour (depth-only passes).
    void set_draw_buffers(const std::vector<int>& colour_indices);

    // Throws std::runtime_error naming the label and the status (e.g.
    // GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT) unless complete.
    void check_complete() const;

    void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, id()); }
    GLuint id() const { return handle_.get(); }
    const std::string& label() const { return label_; }

    static const char* status_name(GLenum status);

private:
    void note_colour_attachment(int index);

    Handle<FramebufferDeleter> handle_;
    std::vector<int> colour_indices_;
    bool explicit_draw_buffers_ = false;
    std::string label_;
};

}  // namespace effects::gl
