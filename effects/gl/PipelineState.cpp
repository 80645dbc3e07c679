#include "effects/gl/PipelineState.h"

namespace effects::gl {

namespace {

void set(GLenum capability, bool on) {
    if (on) glEnable(capability);
    else glDisable(capability);
}

}  // namespace

void apply(const PipelineState& s) {
    set(GL_DEPTH_TEST, s.depth_test);
    glDepthMask(s.depth_write ? GL_TRUE : GL_FALSE);
    glDepthFunc(s.depth_func);
    set(GL_BLEND, s.blend.on);
    glBlendFuncSeparate(s.blend.src_rgb, s.blend.dst_rgb, s.blend.src_alpha, s.blend.dst_alpha);
    glBlendEquation(s.blend.equation);
    set(GL_CULL_FACE, s.cull_back_faces);
    glCullFace(GL_BACK);
    const GLboolean colour = s.colour_write ? GL_TRUE : GL_FALSE;
    glColorMask(colour, colour, colour, colour);
    set(GL_SCISSOR_TEST, s.scissor);
    const bool offset = s.offset_factor != 0.0f || s.offset_units != 0.0f;
    set(GL_POLYGON_OFFSET_FILL, offset);
    glPolygonOffset(s.offset_factor, s.offset_units);
    set(GL_PROGRAM_POINT_SIZE, s.program_point_size);
    glDisable(GL_STENCIL_TEST);
}

}  // namespace effects::gl
