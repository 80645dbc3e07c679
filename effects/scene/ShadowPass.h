#pragma once
#include <optional>

#include <glm/mat4x4.hpp>

#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// The sun's shadow map: an orthographic depth render of the opaque scene over a
// square that follows the camera in steps, snapped to whole texels so edges don't crawl.
class ShadowPass final : public Pass {
public:
    ShadowPass();
    std::string_view name() const override { return "shadow"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

private:
    static constexpr float kCentreStep_m = 8.0f;  // the map follows the camera in steps of this

    gl::Program program_;
    gl::Framebuffer fbo_;
    gl::Texture still_map_;  // the casters that stay put, for the current view of the sun
    gl::Framebuffer still_fbo_;
    std::optional<glm::mat4> still_view_proj_;
    float half_extent_m_ = 70.0f;
    float ahead_m_ = 30.0f;  // centre the map this far in front of the eye
    bool fbo_initialised_ = false;
};

}  // namespace effects
