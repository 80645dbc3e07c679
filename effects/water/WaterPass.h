#pragma once
// The harbour water (docs/effects/water.md, "Rendering"): the wave grid's surface and the
// open sea around it, the airborne splash sheets and the spray, drawn into the scene
// targets after the opaque scene was copied (it refracts the copy). Without a
// sim::WaterSim in the world it draws a flat sea.
#include "effects/scene/Pass.h"
#include "effects/water/SplashFoam.h"
#include "effects/water/SplashSheetRenderer.h"
#include "effects/water/SprayRenderer.h"
#include "effects/water/WaterShading.h"
#include "effects/water/WaterSurfaceRenderer.h"
#include "effects/water/WaterView.h"

namespace effects {

// The tweakable look, registered with the debug panel under "water".
struct WaterLook {
    float foam = 1.0f;              // crest and sheet whitening
    float shore_foam = 0.5f;        // lace where the water is shallow against walls and bodies
    float absorption = 1.0f;        // scales the per-metre absorption
    float refraction = 0.03f;       // screen offset per unit of normal tilt
    float ripples = 1.0f;           // wind ripples on top of the grid's waves
    float sheet_thickness_m = 0.02f;   // at rest; it thins as the sheet stretches
    float sheet_tear_stretch = 12.0f;   // sheet triangles stretched beyond this (linear) have torn
    float triangle_px = 20.0f;      // the wave lattice coarsens far away to about this size
    float splash_foam = 1.0f;       // white water where splashes fall back (0: none)
    FoamLook splash_foam_look;
    bool rim_drops = true;          // beads on the sheets' rims, the drop atop each jet
    SprayLook spray;
};

class WaterPass final : public Pass {
public:
    WaterPass();
    std::string_view name() const override { return "water"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

    // Draws a given view of the water (render() gathers it from the world). Throws
    // std::invalid_argument for an inconsistent view (WaterView::validate).
    void draw(const FrameContext& frame, const WaterView& view);

    WaterLook& look() { return look_; }
    // Triangles of splash sheet drawn by the last frame (for tests and the profiler).
    size_t sheet_triangles() const { return sheets_.mesh().indices.size() / 3; }
    const std::vector<TileDraw>& surface_tiles() const { return surface_.last_tiles(); }
    // The foam left where splashes fell back, as of the last frame.
    const SplashFoam& splash_foam() const { return foam_; }

private:
    static constexpr GLuint kSplashFoamUnit = 7;  // free of WaterShading's and the lighting's

    // The pixels the water's geometry can cover this frame: the shading passes' scissor
    // (the sea's box ends at the horizon, so the sky above it is never masked).
    glm::ivec4 water_rect(const Camera& cam, const SceneTargets& t, bool sheets) const;
    // Follows the splashes, uploads the foam map and points the sea's program at it.
    void update_splash_foam(const WaterView& view, const gl::Program& sea);

    WaterSurfaceRenderer surface_;
    SplashSheetRenderer sheets_;
    SprayRenderer spray_;
    WaterShading shading_;
    SplashFoam foam_;
    gl::Texture foam_map_;  // foam_'s field, or 1x1 of nothing
    int foam_map_side_ = -1;
    WaterView view_;  // reused each frame
    std::vector<SprayDrop> drops_;  // scratch: the spray and the sheets' drops
    WaterLook look_;
};

}  // namespace effects
