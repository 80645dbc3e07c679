#pragma once
#include "effects/scene/Pass.h"

namespace effects {

// Copies the opaque scene's colour and depth (dust included): the scene copy, which every
// pass that refracts what is behind reads. The water reads it as made here; the fluid and
// the rain, later in the frame, copy the colour into it again first (SceneTargets'
// refresh_colour_copy and refresh_colour_copy_with_mips), each declaring the refresh.
class SceneCopyPass final : public Pass {
public:
    std::string_view name() const override { return "scene_copy"; }
    void render(const FrameContext& frame) override { frame.targets.copy_scene(); }
};

}  // namespace effects
