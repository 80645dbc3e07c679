#pragma once
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// The sea surface at rest: Fresnel mix of the sky's reflection and the refracted,
// depth-absorbed scene below.
class SeaPass final : public Pass {
public:
    SeaPass();
    std::string_view name() const override { return "sea"; }
    void render(const FrameContext& frame) override;

private:
    gl::Program program_;
};

}  // namespace effects
