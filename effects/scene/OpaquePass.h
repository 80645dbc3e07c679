#pragma once
#include "effects/gl/Program.h"
#include "effects/scene/LitProgram.h"
#include "effects/scene/Pass.h"

namespace effects {

// The lit opaque scene into the HDR targets: sky background, terrain, props,
// vehicles and thrown objects.
class OpaquePass final : public Pass {
public:
    OpaquePass();
    std::string_view name() const override { return "opaque"; }
    void render(const FrameContext& frame) override;

private:
    LitProgram objects_, ground_;
    gl::Program sky_;
};

}  // namespace effects
