#pragma once
// Rain falling in the world (docs/effects/weather.md): thin streaks, one GL line per
// drop, in a box that follows the eye. The drops are fixed in the world and fall through
// the box, wrapping at its faces; each is drawn as the blur of its fall over a short
// exposure, depth-tested against the scene, blended into the scene's colour. Their
// number follows the sim's rain rate; with no rain the pass draws nothing. Drawn before
// the windshield so that the glass and its drops lie over them.
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// The tweakable look, registered with the debug panel under "rain streaks".
struct RainStreakLook {
    bool enabled = true;
    int drops_at_full_rain = 7000;  // in the whole box
    float box_m = 24.0f;            // the box's width and depth about the eye (height: half that)
    float near_m = 2.0f;            // none nearer: the glass and the cabin are in the way
    float opacity = 0.28f;
    float exposure_s = 0.04f;       // a streak's length is its fall over this long
};

class RainStreakPass final : public Pass {
public:
    RainStreakPass();
    std::string_view name() const override { return "rain_streaks"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

    RainStreakLook& look() { return look_; }
    // Streaks drawn in the last frame (0 when it did not rain).
    int drawn_last_frame() const { return drawn_; }

private:
    gl::Program program_;
    gl::Framebuffer fbo_;
    uint64_t generation_ = 0;  // SceneTargets::generation() fbo_ was built for
    RainStreakLook look_;
    int drawn_ = 0;
};

}  // namespace effects
