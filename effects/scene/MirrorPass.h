#pragma once
#include <memory>
#include <optional>

#include <glm/vec3.hpp>

#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/scene/GpuModel.h"
#include "effects/scene/LitScene.h"
#include "effects/scene/Pass.h"

namespace effects {

// The car's rear-view mirror, after the opaque scene: the view behind, from the mirror,
// into a small picture, then that picture on the mirror's glass (mirrored left to right),
// over the sky the opaque pass reflected there. Only from the driver's seat with the
// mirror on screen, and cheaply: the opaque scene without the car itself (terrain, props,
// the boat, thrown objects and markers, culled to its frustum), a flat sea and the sky;
// no water, rain, dust or fluid. The quality preset sets the picture's size or turns it off.
class MirrorPass final : public Pass {
public:
    MirrorPass();
    std::string_view name() const override { return "mirror"; }
    void render(const FrameContext& frame) override;
    bool drawn_last_frame() const { return drawn_; }

    // The mirror's glass in the car's model space: the "mirror_glass" mesh of its model.
    struct Glass {
        glm::vec3 centre{0.0f};
        glm::vec3 normal{0.0f};            // out of the glass, towards the seat
        glm::vec3 across{0.0f}, up{0.0f};  // unit axes on the glass: the driver's right, and up
        float half_width = 0.0f, half_height = 0.0f;
    };
    static std::optional<Glass> find_glass(const SceneDesc& desc);

private:
    struct View;
    void draw_behind(const FrameContext& frame, const View& view);
    void draw_glass(const FrameContext& frame, const View& view);

    LitScene scene_;
    gl::Program glass_program_;
    bool looked_up_ = false;
    std::optional<Glass> glass_;
    std::unique_ptr<GpuModel> glass_model_;
    int width_ = 0, height_ = 0;
    gl::Texture colour_, depth_;
    gl::Framebuffer fbo_;
    bool drawn_ = false;
};

}  // namespace effects
