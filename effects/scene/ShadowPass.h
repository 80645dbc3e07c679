#pragma once
#include <cstdint>
#include <optional>

#include <glm/mat4x4.hpp>

#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// The sun's shadow map: an orthographic depth render of the opaque scene from
// FrameData::sun_shadow_view_proj (a square that follows the camera in steps).
class ShadowPass final : public Pass {
public:
    ShadowPass();
    std::string_view name() const override { return "shadow"; }
    void render(const FrameContext& frame) override;

private:
    gl::Program program_;
    gl::Framebuffer fbo_;
    gl::Texture still_map_;  // the casters that stay put, for the current view of the sun
    gl::Framebuffer still_fbo_;
    std::optional<glm::mat4> still_view_proj_;
    uint64_t still_terrain_ = 0;  // SceneGeometry::terrain_generation() of the still map
    bool fbo_initialised_ = false;
};

}  // namespace effects
