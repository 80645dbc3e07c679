#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

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
    // Texel rectangles {x0, y0, x1, y1} the last frame's moving casters may have drawn
    // over the still map's copy: only those are restored from it the next frame.
    std::vector<glm::ivec4> dirty_;
    bool whole_copy_needed_ = true;
};

}  // namespace effects
