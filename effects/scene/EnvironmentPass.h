#pragma once
#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// Fills the environment cube from the analytic sky whenever the sky changes.
class EnvironmentPass final : public Pass {
public:
    EnvironmentPass();
    std::string_view name() const override { return "environment"; }
    void render(const FrameContext& frame) override;

private:
    gl::Program program_;
    gl::Framebuffer fbo_;
    SkyState filled_{};
    bool valid_ = false;
};

}  // namespace effects
