#pragma once
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// HDR scene colour to the output (or the display image): exposure, ACES filmic curve, sRGB.
class TonemapPass final : public Pass {
public:
    TonemapPass();
    std::string_view name() const override { return "tonemap"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

private:
    gl::Program program_;
    float exposure_ = 0.9f;
};

}  // namespace effects
