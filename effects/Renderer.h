#pragma once
// The frame: the ordered pass list of PassList.cpp run over shared scene resources,
// each pass in a debug group and timed.
#include <memory>
#include <vector>

#include "effects/Quality.h"
#include "effects/PassList.h"
#include "effects/gl/PassTimer.h"
#include "effects/scene/Pass.h"

namespace effects {

struct RendererOptions {
    int environment_size = 64;
    gl::TimingMode timing = gl::TimingMode::GpuQueries;
};

class Renderer {
public:
    Renderer(const SceneDesc& scene, const sim::World& world, RendererOptions options = {});

    void render(const sim::World& world, RenderOutput output);
    // The same with the moving things where `poses` puts them (between two ticks).
    void render(const sim::World& world, RenderOutput output, const FramePoses& poses);

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
    static constexpr float kMinRenderScale = 0.25f;

    const SceneTargets& targets() const { return resources_.targets; }
    // Whether the frame draws world normals into targets() (SceneTargets::write_normals):
    // off unless a capture reads them.
    void write_normals(bool on) { resources_.targets.write_normals(on); }
    ParamRegistry& params() { return params_; }
    const std::vector<gl::PassTime>& pass_times() const { return timer_->results(); }
    const std::vector<std::unique_ptr<Pass>>& passes() const { return passes_; }
    // Profile mode brackets each pass with glFinish: exact where timer queries read ~0.
    void set_timing(gl::TimingMode mode);
    gl::TimingMode timing() const { return timer_->mode(); }

private:
    SceneResources resources_;
    FrameData data_;  // gathered once a frame, before the passes
    std::vector<std::unique_ptr<Pass>> passes_;
    std::unique_ptr<gl::PassTimer> timer_;
    ParamRegistry params_;
    glm::vec3 sun_dir_;
    Quality quality_ = Quality::High;
    float render_scale_ = 1.0f;
};

}  // namespace effects
