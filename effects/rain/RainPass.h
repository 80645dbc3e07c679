#pragma once
// Windshield rain (docs/effects/rain.md, "What is implemented"): in the driver's view,
// the drops' height map is built over the glass, and the windshield is drawn over the
// finished scene (after the water, before tonemapping), each drop refracting a blurred
// copy of the scene and reflecting the sky, with the wiper blades on top. Not in the
// driver's view, or with a dry glass and parked wipers, it does nothing at all.
#include <memory>

#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/rain/DropHeightMap.h"
#include "effects/rain/RainView.h"
#include "effects/rain/WindshieldMesh.h"
#include "effects/scene/Pass.h"

namespace effects {

// The tweakable look, registered with the debug panel under "rain".
struct RainLook {
    bool enabled = true;        // off: the pass draws nothing (to compare with and without)
    float radius_scale = 3.5f;  // drops drawn this much wider than their contact radius, to read on screen
    float refraction = 0.08f;   // screen offset (of its height) per unit of normal tilt
    float blur_lod = 2.5f;      // mip of the scene behind a drop 1 m from the eye, at 360 lines: out of focus
    float rim = 0.4f;           // darkening at a drop's steep edge (light bent away)
    int compression_steps = 0;  // the seed's height compression, off (DropHeightMap.h)
};

class RainPass final : public Pass {
public:
    explicit RainPass(int height_map_width = 1024, int height_map_height = 512);
    std::string_view name() const override { return "rain"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

    // Draws a given view (render() gathers it from the world).
    void draw(const FrameContext& frame, const RainView& view);

    RainLook& look() { return look_; }
    bool drew_last_frame() const { return drew_; }

private:
    DropHeightMap height_map_;
    int made_width_, made_height_;  // the size asked for at construction: the high preset's
    gl::Program shade_;
    std::unique_ptr<WindshieldMesh> mesh_;
    gl::Texture behind_;  // the finished scene with mips, for the out-of-focus refraction
    gl::Framebuffer behind_fbo_, scene_colour_fbo_;
    int behind_w_ = 0, behind_h_ = 0;
    RainView view_;  // reused each frame
    RainLook look_;
    bool drew_ = false;
};

}  // namespace effects
