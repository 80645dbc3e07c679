#pragma once
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// The tone-mapped frame from the scene's size to the output's when the renderer draws
// the scene smaller than the output (dynamic resolution, presets): an edge-adaptive
// upscale with contrast-adaptive sharpening (shaders/scene/upscale.frag.glsl). Does
// nothing at a render scale of 1, where the tone map or the anti-aliasing writes the
// output itself.
class UpscalePass final : public Pass {
public:
    UpscalePass();
    std::string_view name() const override { return "upscale"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

private:
    gl::Program program_;
    float edge_ = 0.5f;  // fully steepened, a low scale's aliased edges read as stairs
    float sharpness_ = 0.5f;
};

}  // namespace effects
