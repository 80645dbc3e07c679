#pragma once
#include "effects/scene/Pass.h"

namespace effects {

// Copies the opaque scene's colour and depth (dust included) for the water, the only
// pass that reads the copy: the sea refracts and absorbs what lies below it. The fluid
// and the rain copy the scene colour into targets of their own, later in the frame.
class SceneCopyPass final : public Pass {
public:
    std::string_view name() const override { return "scene_copy"; }
    void render(const FrameContext& frame) override { frame.scene.targets.copy_scene(); }
};

}  // namespace effects
