#pragma once
// Deferred water shading. The water's geometry (sea surface, splash sheets) is first
// drawn with a cheap shader that writes depth, the scene normal and a small "water
// kind" target; then full-screen passes shade each water pixel exactly once
// (reflection, refraction, absorption, foam, fog). A software rasteriser shades every
// partly covered 4x4 block of every triangle, and runs a shader to its end even for
// pixels it discards: so the dense wave mesh only pays for the cheap shader, and the
// shading passes are depth-tested against a mask of the water pixels (made from the
// kind target) so that nothing else is shaded at all.
#include "effects/Quality.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/scene/FrameContext.h"
#include "effects/scene/LitProgram.h"

namespace effects {

class WaterShading {
public:
    static constexpr GLuint kDepthUnit = 4, kNormalUnit = 5, kKindUnit = 6;

    WaterShading();

    // Binds the geometry framebuffer (scene depth, scene normal as output 0, the kind
    // target as output 1) with the kind target cleared. Follows resizes of the scene.
    // The kind target (GL_RGBA8, what a software rasteriser writes fastest): red 0 =
    // no water, 0.5 = sea, 0.76..1 = splash sheet (more for a thicker film); green their
    // foam weight; blue a sheet's opacity.
    void begin_geometry(const SceneTargets& targets);
    // Shades the water pixels into the scene colour: the sea, then the splash sheets
    // if there are any, within `rect` ({x0, y0, x1, y1}, x1/y1 exclusive: where the
    // geometry step can have drawn; the mask pass costs a fill of whatever it covers).
    // The programs' uniforms (lighting, camera, scene copies, look) must be set by the
    // caller first.
    void shade(const SceneTargets& targets, bool sheets, glm::ivec4 rect);

    // One program per kind: a software rasteriser would run both kinds' code for
    // every pixel of a shader that branches between them.
    // The shading programs lit as the preset and the frame's line lights ask.
    void select_programs(const QualitySettings& quality, bool line_lights);
    const gl::Program& sea_program() const { return *sea_program_; }
    const gl::Program& sheet_program() const { return *sheet_program_; }
    const gl::Texture& kind() const { return kind_; }

private:
    LitProgram sea_, sheet_;
    const gl::Program *sea_program_ = nullptr, *sheet_program_ = nullptr;
    gl::Program mask_;
    gl::Texture kind_, mask_depth_;
    gl::Framebuffer geometry_fbo_, shade_fbo_;
    GLuint colour_id_ = 0, normal_id_ = 0, depth_id_ = 0;  // the scene textures the framebuffers hold
};

}  // namespace effects
