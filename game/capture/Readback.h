#pragma once
#include "effects/gl/Gl.h"
#include "game/capture/Image.h"

#include <vector>

namespace game {

// Reads pixels (0,0)-(w,h) of a framebuffer on the current context, rows flipped
// to top-down (GL's row 0 is the bottom). Waits for the GPU. Restores the pack state
// and read framebuffer binding it changes. Throws std::invalid_argument for a size
// outside 1..16384 and std::runtime_error for an incomplete framebuffer or a GL error.
// `attachment` selects the colour attachment of a framebuffer object (ignored for 0).
ImageRGBA8 read_framebuffer_rgba8(GLuint framebuffer, int width, int height,
                                  GLenum attachment = GL_COLOR_ATTACHMENT0);
ImageRGBA32F read_framebuffer_rgba32f(GLuint framebuffer, GLenum attachment, int width,
                                      int height);
// Depth values in [0, 1], width*height floats, rows top-down.
std::vector<float> read_depth(GLuint framebuffer, int width, int height);

}  // namespace game
