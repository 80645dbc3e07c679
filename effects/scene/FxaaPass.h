#pragma once
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// Anti-aliasing of the whole frame (FXAA, shaders/scene/fxaa.frag.glsl) when the
// preset or the player turns it on (`quality.antialias`): reads the tone-mapped display
// image and writes the output at a render scale of 1, else the anti-aliased image that
// the upscale brings to the output. It runs at the scene's size, before the upscale:
// a quarter to a half of the pixels at auto's usual scales, and the stairs it smooths
// are the scene's own pixels, which the upscale would only magnify.
class FxaaPass final : public Pass {
public:
    FxaaPass();
    std::string_view name() const override { return "fxaa"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

private:
    gl::Program program_;
    float subpixel_ = 0.75f;         // Lottes' default: specks softened, texture kept
    float threshold_ = 0.166f;       // his "high quality" edge threshold
    float threshold_min_ = 0.0833f;  // and its floor, so dark noise stays as it is
};

}  // namespace effects
