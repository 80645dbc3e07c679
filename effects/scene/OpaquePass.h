#pragma once
#include "effects/scene/LitScene.h"
#include "effects/scene/Pass.h"

namespace effects {

// The lit opaque scene into the HDR targets: sky background, terrain, props,
// vehicles and thrown objects (and their normals, when SceneTargets draws them).
class OpaquePass final : public Pass {
public:
    OpaquePass();
    std::string_view name() const override { return "opaque"; }
    void render(const FrameContext& frame) override;

private:
    LitScene scene_;
};

}  // namespace effects
