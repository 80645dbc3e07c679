#pragma once
// Windshield rain (docs/effects/rain.md, "What is implemented"): in the driver's view,
// the drops' height map is built over the glass, and the windshield is drawn over the
// finished scene (after the water, before tonemapping), each drop refracting a blurred
// copy of the scene and reflecting the sky, with the wiper blades on top. Not in the
// driver's view, or with a dry glass and parked wipers, it does nothing at all.
#include <cstdint>
#include <memory>
#include <vector>

#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Sampler.h"
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
    float refraction = 0.2f;    // screen heights the lookup moves per unit of normal tilt: a drop's image flips...
    float reach = 16.0f;        // ...but at most this many of the drop's radii on screen
    float blur_bias = 0.5f;     // mip bias of the image in a drop: the eye is focused on the road
    float glint = 1.5f;         // the sun's highlight, times the sun's radiance
    float film = 0.5f;          // how much the wet streak behind a runner blurs and brightens the view
    int compression_steps = 0;  // the seed's height compression, off (DropHeightMap.h)
    bool wet_cells_only = true; // off: every cell of the windshield is shaded (WindshieldCells.h; the same image)
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
    // The windshield cells shaded last frame, of how many (WindshieldCells.h).
    size_t cells_drawn() const;
    size_t cells_total() const { return shown_.size(); }

private:
    void upload_film(const RainView& view);

    DropHeightMap height_map_;
    int made_width_, made_height_;  // the size asked for at construction: the most the map grows to
    gl::Program shade_;
    std::unique_ptr<WindshieldMesh> mesh_;
    // The scene copy's mips read trilinearly, for the out-of-focus refraction.
    gl::Sampler behind_sampler_;
    gl::Texture film_;  // RainView::film, one texel a glass cell
    int film_cols_ = 0, film_rows_ = 0;
    gl::Framebuffer scene_colour_fbo_;
    uint64_t scene_generation_ = 0;  // SceneTargets::generation() scene_colour_fbo_ was built for
    std::vector<uint8_t> shown_;  // the windshield cells drawn this frame (WindshieldCells.h)
    RainView view_;  // reused each frame
    RainLook look_;
    bool drew_ = false;
};

}  // namespace effects
