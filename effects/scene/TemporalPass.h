#pragma once
#include <cstdint>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "effects/Quality.h"
#include "effects/gl/Program.h"
#include "effects/scene/Camera.h"
#include "effects/scene/Pass.h"

namespace effects {

// Temporal upsampling's resolve (shaders/scene/temporal.frag.glsl), at the scene's size
// when QualitySettings::temporal is on: each frame is drawn with the projection moved by
// a sub-pixel jitter (temporal_jitter_px, Renderer::prepare), and this pass blends the
// tone-mapped frame with the last resolved one, reprojected through the depth from the
// last frame's view to this one's and clamped to the range of the pixel's
// neighbourhood (so what moved, or came into view, does not leave a ghost). Each pixel
// has two candidates for where it was: the world's (the world taken as still) and the
// vehicle's nearest the eye (through its last and this pose, so the car's cabin in the
// driver's view, or the car ahead of the chase camera, keeps its history); the one
// nearer this frame's colour is taken. Over a few frames an edge's pixels take its
// coverage instead of all-or-nothing: the scene is anti-aliased before the upscale
// enlarges it, and a small scene's stairs do not show.
// Each pixel is reprojected at the nearest depth around it, so a near object's
// silhouette moves with the object rather than partly with the background behind it.
// Most of the neighbourhood (8 of the 3x3) is read through the fine derivatives rather
// than fetched: on llvmpipe every fetch costs about as much as the arithmetic of a whole
// pixel. Only the pixels of the vehicle's screen box fetch its candidate. Without
// FXAA it reads the HDR colour and does the tone map itself (tonemapped_by_temporal):
// one pass over the scene's pixels instead of two, and one image fewer written and read.
class TemporalPass final : public Pass {
public:
    TemporalPass();
    std::string_view name() const override { return "temporal"; }
    void render(const FrameContext& frame) override;

private:
    // [from_hdr][vehicle]: from_hdr tone maps the HDR colour as it resolves it (else it
    // resolves the tone-mapped display image, after FXAA); vehicle adds the vehicle's
    // candidate (drawn over its screen box only).
    gl::Program programs_[2][2];
    bool has_history_ = false;
    uint64_t history_generation_ = 0;  // SceneTargets' generation the history was drawn at
    glm::mat4 last_view_proj_{1.0f};   // the last frame's, without its jitter
    glm::mat4 last_vehicle_{1.0f};     // the last frame's pose of the vehicle nearest the eye
};

// How the resolve blends at a scene scale: how wide the jitter spreads (in the scene's
// pixels) and this frame's weight against the history.
struct TemporalBlend {
    float jitter_spread;
    float current_weight;
};
// At 0.5 and above, sharp: the jitter half a scene pixel wide, its samples on the output
// pixels' own centres inside the scene's pixel (the native frame's samples), and about
// the last 3 frames kept (each one more a fraction of a pixel off the native frame's
// samples). At auto's floor, 0.35, smooth: a stair of one frame is 2.86 output pixels,
// and only the whole pixel's samples over about 7 frames take it under 2, standing or
// moving (TemporalEdgeTest). Linear between. Measured at harbour_rain 1690 at 0.5
// (SSIM against native): 0.902 sharp; 0.882 with the floor's weight; 0.877 with the
// floor's weight and spread.
TemporalBlend temporal_blend(float scene_scale);

// The sub-pixel offset (in the scene's pixels, each axis within half the spread of
// the centre) of the projection for the `frame`th frame drawn with temporal
// upsampling at `scene_scale`: the Halton (2, 3) sequence's first eight points, again
// and again, so that every eight frames sample the spread evenly.
glm::vec2 temporal_jitter_px(uint64_t frame, float scene_scale);

// `camera`'s view-projection without its jitter.
glm::mat4 unjittered_view_proj(const Camera& camera);

// From this frame's window position and depth to the last frame's clip space (its view
// `last_view_proj`, unjittered), the world taken as still. The position is the pixel's
// centre without this frame's jitter: the history holds the picture unjittered, so a
// still view reads it at its texels' centres (no resampling, no blur), and the jittered
// sample this frame adds lands a sub-pixel off the centre, which is what averages an
// edge's coverage over the frames.
glm::mat4 history_reprojection(const glm::mat4& last_view_proj, const Camera& camera);

// Whether TemporalPass tone maps the frame (and TonemapPass draws nothing): temporal
// upsampling on, FXAA off (FXAA reads the tone-mapped image).
inline bool tonemapped_by_temporal(const QualitySettings& q) { return q.temporal && !q.antialias; }

}  // namespace effects
