#pragma once
#include "effects/scene/Pass.h"

namespace effects {

// Copies the opaque scene's colour and depth for the passes that look through
// surfaces (sea, fluid tank, windshield).
class SceneCopyPass final : public Pass {
public:
    std::string_view name() const override { return "scene_copy"; }
    void render(const FrameContext& frame) override { frame.scene.targets.copy_scene(); }
};

}  // namespace effects
