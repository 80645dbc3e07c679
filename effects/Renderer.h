#pragma once
// The frame: the ordered pass list of PassList.cpp run over shared scene resources,
// each pass in a debug group and timed.
#include <memory>
#include <vector>

#include "effects/gl/PassTimer.h"
#include "effects/scene/Pass.h"

namespace effects {

struct RendererOptions {
    int shadow_map_size = 1024;
    int environment_size = 64;
    gl::TimingMode timing = gl::TimingMode::GpuQueries;
};

class Renderer {
public:
    Renderer(const SceneDesc& scene, const sim::World& world, RendererOptions options = {});

    void render(const sim::World& world, RenderOutput output);

    const SceneTargets& targets() const { return resources_.targets; }
    ParamRegistry& params() { return params_; }
    const std::vector<gl::PassTime>& pass_times() const { return timer_->results(); }
    const std::vector<std::unique_ptr<Pass>>& passes() const { return passes_; }
    // Profile mode brackets each pass with glFinish: exact where timer queries read ~0.
    void set_timing(gl::TimingMode mode);
    gl::TimingMode timing() const { return timer_->mode(); }

private:
    SceneResources resources_;
    std::vector<std::unique_ptr<Pass>> passes_;
    std::unique_ptr<gl::PassTimer> timer_;
    ParamRegistry params_;
    glm::vec3 sun_dir_;
};

// The passes in frame order (effects/PassList.cpp).
std::vector<std::unique_ptr<Pass>> make_pass_list();

}  // namespace effects
