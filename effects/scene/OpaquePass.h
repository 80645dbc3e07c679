#pragma once
#include <optional>

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
    LitProgram objects_;
    std::optional<LitProgram> ground_;  // made at the first frame: it needs the level's road count
    gl::Program sky_;
};

}  // namespace effects
