#pragma once
// Deferred water shading. The water's geometry is first drawn with a cheap shader: the
// sea surface writes depth only, the splash sheets depth, the scene normal and a small
// "water kind" target; then full-screen passes shade each water pixel exactly once
// (normal and crests for the sea, reflection, refraction, absorption, foam, fog). A
// software rasteriser shades every partly covered 4x4 block of every triangle, and runs
// a shader to its end even for pixels it discards: so the dense wave mesh only pays
// for depth, and the shading passes are depth-tested against a mask of the water
// pixels (the sea where the scene's depth is nearer than the copy taken before the
// water, the sheets where the kind target says so) so that nothing else is shaded.
#include "effects/Quality.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/scene/FrameContext.h"
#include "effects/scene/LitProgram.h"

namespace effects {

class WaterShading {
public:
    static constexpr GLuint kColourCopyUnit = 0, kDepthCopyUnit = 1, kDepthUnit = 4, kNormalUnit = 5, kKindUnit = 6;

    WaterShading();

    // Bind the geometry framebuffers, following resizes of the scene. The sea's: the
    // scene depth only. The sheets': the scene depth, the scene normal as output 0 and
    // the kind target as output 1, cleared (GL_RGBA8, what a software rasteriser writes
    // fastest: red 0 = no sheet, 0.76..1 = splash sheet, more for a thicker film; green
    // its foam weight; blue its opacity). Draw the sea first: the mask takes a kind
    // written this frame as a sheet in front of it.
    void begin_sea(const SceneTargets& targets);
    void begin_sheets(const SceneTargets& targets);
    // Shades the water pixels into the scene colour: the sea, then the splash sheets
    // if there are any, within `rect` ({x0, y0, x1, y1}, x1/y1 exclusive: where the
    // geometry step can have drawn; the mask pass costs a fill of whatever it covers).
    // Binds the scene copies and its own inputs; the programs' other uniforms (lighting,
    // camera, grid, look) must be set by the caller first.
    void shade(const SceneTargets& targets, bool sheets, glm::ivec4 rect);

    // One program per kind: a software rasteriser would run both kinds' code for
    // every pixel of a shader that branches between them.
    // The shading programs lit as the preset and the frame's line lights ask.
    void select_programs(const QualitySettings& quality, bool line_lights);
    const gl::Program& sea_program() const { return *sea_program_; }
    const gl::Program& sheet_program() const { return *sheet_program_; }

private:
    void follow_targets(const SceneTargets& targets);

    LitProgram sea_, sheet_;
    const gl::Program *sea_program_ = nullptr, *sheet_program_ = nullptr;
    gl::Program sea_mask_, sea_and_sheet_mask_;  // the latter reads the kind target
    gl::Texture kind_, mask_depth_;
    gl::Framebuffer sea_fbo_, sheet_fbo_, shade_fbo_;
    uint64_t generation_ = 0;  // SceneTargets::generation() the framebuffers were built for
};

}  // namespace effects
