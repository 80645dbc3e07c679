#pragma once
// Dynamic resolution for `--quality auto`: the 3D scene's render scale chosen from the
// last frames' times, to hold a frame-time budget (the game's: auto_frame_budget_ms).
#include <cstddef>
#include <deque>

namespace game {

// Pure logic: fed one frame time per frame, it answers the render scale for the next.
// Slow frames bring the scale down fast (a few frames, in a step sized by how far over
// they are: pixels cost about the scale squared); a long run of frames nearly all well
// under the budget brings it up one small step (a frame that ran two ticks, or a
// scheduler's hiccup, among them does not keep the picture coarse): "well under" is
// judged at the next step's size, each frame's time grown with the pixels (scale
// squared) but for its fixed share, and kept under up_fraction of the budget, so that a
// step up does not overrun the budget and come straight back. Between the two it holds, and after a change it first measures frames
// at the new scale, so it never changes every frame.
class ResolutionController {
public:
    struct Options {
        double budget_ms = 30.0;       // a 30 fps target with a little to spare
        double up_fraction = 0.95;     // "well under": below this part of the budget at the next step's size
        // The part of a frame that does not shrink with the scene's pixels (the upscale,
        // the UI, the sim, the shadow map, the draws' set-up): about a quarter of auto's
        // frame at 0.5 in the timedemo's passes.
        double fixed_share = 0.25;
        float min_scale = 0.35f;
        float max_scale = 1.0f;
        float start_scale = 0.75f;     // medium's
        float step = 0.05f;            // scales are multiples of this
        size_t down_window = 6;        // frames judged for a step down (the worst one ignored)
        size_t up_frames = 45;         // frames judged for a step up
        double up_share = 0.9;         // the share of them that must be well under the budget
    };

    ResolutionController() : ResolutionController(Options{}) {}
    explicit ResolutionController(const Options& options);

    // The time of the frame just drawn at scale(); returns the scale for the next one.
    float frame(double frame_ms);
    float scale() const { return scale_; }
    const Options& options() const { return options_; }

private:
    float snap(float scale) const;

    Options options_;
    float scale_;
    std::deque<double> recent_;  // frame times at the current scale, newest last (up_frames at most)
};

// The game's budget on auto: the frame target of 15 trivial fills (FrameTargets.h; 30 fps
// on a host whose fill of the output takes 2.2 ms), or 30 ms where that is less (a slow or
// busy host's fills are slow too, and a frame in fills does not say it is fast enough to
// play). `fill_ms`: a trivial fill of the output (game/bench/TrivialFill.h); 30 ms
// without one.
double auto_frame_budget_ms(double fill_ms);

}  // namespace game
