#pragma once
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// The sky's occlusion map: an orthographic depth render of the props straight down
// (FrameData::sky_occlusion_view_proj), once (they never move), so that lit surfaces
// under a roof (the warehouse's floor, walls and crates, under the pier) lose the sky's
// ambient light and reflection.
class SkyOcclusionPass final : public Pass {
public:
    SkyOcclusionPass();
    std::string_view name() const override { return "sky occlusion"; }
    void render(const FrameContext& frame) override;

private:
    gl::Program program_;
    gl::Framebuffer fbo_;
    bool drawn_ = false;
};

}  // namespace effects
