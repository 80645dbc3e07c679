#pragma once
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// The tone-mapped frame from the scene's size to the output's when the renderer draws
// the scene smaller than the output (dynamic resolution, presets): one bilinear fetch a
// pixel, its place within the texel steepened a little (shaders/scene/upscale.frag.glsl);
// at auto what it enlarges is anti-aliased first (TemporalPass). Does nothing at a render
// scale of 1, where the tone map or the anti-aliasing writes the output itself, unless
// the temporal resolve holds the frame (then it copies it).
class UpscalePass final : public Pass {
public:
    UpscalePass();
    std::string_view name() const override { return "upscale"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

private:
    gl::Program program_;
    float edge_ = 0.25f;  // more, and a small scene's pixels read as blocks
};

}  // namespace effects
