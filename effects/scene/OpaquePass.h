#pragma once
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
    // The mesh programs for a shadow filter (SHADOW_TAPS), rebuilt when the preset's changes.
    void build_mesh_programs(int shadow_taps);

    gl::Program objects_, ground_, sky_;
    int shadow_taps_ = 0;
};

}  // namespace effects
