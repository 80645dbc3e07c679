#pragma once
// The frame: the frame data gathered once (and its line lights uploaded), then the
// passes of PassList.cpp it holds, in the table's order, over shared render resources,
// each in a debug group and timed. The only place passes are run: the game, the
// replays, the render stage and the benches.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "effects/Quality.h"
#include "effects/PassList.h"
#include "effects/gl/DrawCount.h"
#include "effects/gl/PassTimer.h"
#include "effects/scene/Pass.h"

namespace effects {

struct RendererOptions {
    int environment_size = 64;
    gl::TimingMode timing = gl::TimingMode::GpuQueries;
    PassSet passes = PassSet::all();  // the passes the renderer holds
    // The settings it starts with (set_quality replaces them); the shadow map is made at
    // their size.
    QualitySettings quality = quality_settings(Quality::High);
};

// What one frame does differently from the game's.
struct FrameRequest {
    PassSet skip;                  // held passes left out of this frame
    std::optional<double> time_s;  // FrameContext::time_s; the world's tick time without
    // The passes in `replaced` are drawn by `replacement` instead, in their place: a
    // caller's own view of the sim (a pass's draw(frame, view)).
    PassSet replaced;
    std::function<void(const FrameContext&)> replacement;
    std::optional<Camera> camera;        // instead of the poses' camera at the output's aspect
    std::optional<WeatherLook> weather;  // instead of the world's
    std::optional<SkyState> sky;         // instead of the sky under the weather
    std::optional<EnergyView> energy;    // instead of the world's shots (their glow and line lights)
};

class Renderer {
public:
    Renderer(const SceneDesc& scene, const sim::World& world, RendererOptions options = {});

    void render(const sim::World& world, RenderOutput output);
    // The same with the moving things where `poses` puts them (between two ticks).
    void render(const sim::World& world, RenderOutput output, const FramePoses& poses,
                const FrameRequest& request = {});
    // Sizes the scene for `output` and gathers the frame's data, without running a pass:
    // the context a caller hands a pass's own draw. Valid until the next frame.
    FrameContext prepare(const sim::World& world, RenderOutput output, const FramePoses& poses,
                         const FrameRequest& request = {});
    // The scene's targets at `width` x `height` (times the render scale) of output.
    void size_scene(int width, int height);

    // The preset's settings; its render scale becomes the current one.
    void set_quality(Quality quality);
    Quality quality() const { return quality_; }
    const QualitySettings& quality_settings() const { return resources_.quality; }
    // The 3D scene renders at this fraction of the output's size (clamped to
    // [kMinRenderScale, 1]) and is upscaled to it; the HUD stays at the output's.
    void set_render_scale(float scale);
    float render_scale() const { return render_scale_; }
    // Anti-aliasing (FXAA) on or off; the preset's choice until the next set_quality.
    void set_antialiasing(bool on) { resources_.quality.antialias = on; }
    bool antialiasing() const { return resources_.quality.antialias; }
    // Temporal upsampling (QualitySettings::temporal) on or off; off after set_quality.
    // Its jitter follows the frames drawn with it on, so a given sequence of frames is
    // drawn the same every time.
    void set_temporal(bool on) { resources_.quality.temporal = on; }
    bool temporal() const { return resources_.quality.temporal; }
    static constexpr float kMinRenderScale = 0.25f;

    const SceneTargets& targets() const { return targets_; }
    SceneTargets& targets() { return targets_; }
    SceneLighting& lighting() { return lighting_; }
    // Between frames only: during one, passes read the resources through FrameContext.
    RenderResources& resources() { return resources_; }
    const FrameData& frame_data() const { return data_; }  // the last frame's
    // Whether the frame draws world normals into targets() (SceneTargets::write_normals):
    // off unless a capture reads them.
    void write_normals(bool on) { targets_.write_normals(on); }
    ParamRegistry& params() { return params_; }
    const std::vector<gl::PassTime>& pass_times() const { return timer_->results(); }
    // The last frame's draw calls and triangles per pass that drew any (gl/DrawCount.h).
    struct PassDraws {
        std::string name;
        gl::DrawCount count;
    };
    const std::vector<PassDraws>& pass_draws() const { return pass_draws_; }
    const std::vector<std::unique_ptr<Pass>>& passes() const { return passes_; }
    // Profile mode brackets each pass with glFinish: exact where timer queries read ~0.
    void set_timing(gl::TimingMode mode);
    gl::TimingMode timing() const { return timer_->mode(); }

private:
    RenderResources resources_;
    SceneLighting lighting_;  // maps the environment, shadow and sky-occlusion passes draw
    SceneTargets targets_;
    FrameData data_;  // gathered once a frame, before the passes
    Camera camera_;   // the frame's
    std::vector<std::unique_ptr<Pass>> passes_;
    std::vector<size_t> pass_indices_;  // each held pass's row in the pass table
    std::unique_ptr<gl::PassTimer> timer_;
    ParamRegistry params_;
    glm::vec3 sun_dir_;
    ShadowFraming shadow_framing_;
    BeamLighting beam_lighting_;
    glm::mat4 sky_occlusion_view_proj_;  // the props stay put
    Quality quality_ = Quality::High;
    float render_scale_ = 1.0f;
    std::vector<PassDraws> pass_draws_;
    uint64_t temporal_frame_ = 0;  // frames drawn with temporal upsampling on: the jitter's index
};

}  // namespace effects
