#pragma once
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// HDR scene colour to the output (or the display image): exposure, ACES filmic curve, sRGB.
// With temporal upsampling on and no FXAA, TemporalPass reads the HDR colour and tone
// maps it itself (one pass at the scene's size instead of two), and this draws nothing.
class TonemapPass final : public Pass {
public:
    TonemapPass();
    std::string_view name() const override { return "tonemap"; }
    void render(const FrameContext& frame) override;

private:
    gl::Program program_;
};

}  // namespace effects
