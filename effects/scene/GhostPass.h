#pragma once
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// The ghost (FramePoses::ghost, play --ghost): a replay's car or boat raced beside the
// player's, drawn as a see-through copy, its own nearest surface only (its depth laid
// first, so its inside does not show through its shell), over the water and under the
// glow and the rain. Draws nothing without a ghost: every other frame is as before.
class GhostPass final : public Pass {
public:
    GhostPass();
    std::string_view name() const override { return "ghost"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

private:
    gl::Program program_;
    float opacity_ = 0.3f;         // face on; the rim is more opaque
    float rim_ = 0.55f;            // the outline's extra opacity, edge on
    glm::vec3 tint_{0.55f, 0.85f, 1.0f};  // pale blue-white: no car in the harbour has it
};

}  // namespace effects
