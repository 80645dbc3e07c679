#pragma once
#include <optional>

#include "effects/gl/Program.h"
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
    // The mesh programs for a preset's lighting (shaders' SHADOW_TAPS, ENV_REFLECTION,
    // GROUND_DETAIL), rebuilt when the preset changes.
    void build_mesh_programs(const QualitySettings& quality);

    gl::Program objects_, ground_, sky_;
    std::optional<QualitySettings> built_for_;
};

}  // namespace effects
