#include "effects/Renderer.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "effects/gl/DebugGroup.h"

namespace effects {

Renderer::Renderer(const SceneDesc& scene, const sim::World& world, RendererOptions options)
    : resources_{scene, SceneGeometry(scene, world.terrain()),
                 SceneLighting(options.environment_size, effects::quality_settings(Quality::High).shadow_map_size),
                 SceneTargets{}, effects::quality_settings(Quality::High)},
      passes_(make_pass_list()),
      timer_(std::make_unique<gl::PassTimer>(options.timing)),
      sun_dir_(glm::normalize(world.level().sun_direction)) {
    for (auto& p : passes_) p->register_params(params_);
}

void Renderer::set_timing(gl::TimingMode mode) {
    if (mode != timer_->mode()) timer_ = std::make_unique<gl::PassTimer>(mode);
}

void Renderer::set_quality(Quality quality) {
    quality_ = quality;
    resources_.quality = effects::quality_settings(quality);
    set_render_scale(resources_.quality.render_scale);
}

void Renderer::set_render_scale(float scale) {
    render_scale_ = std::clamp(std::isfinite(scale) ? scale : 1.0f, kMinRenderScale, 1.0f);
}

void Renderer::render(const sim::World& world, RenderOutput output) { render(world, output, capture_poses(world)); }

void Renderer::render(const sim::World& world, RenderOutput output, const FramePoses& poses) {
    const int width = std::max(1, int(std::lround(float(output.width) * render_scale_)));
    const int height = std::max(1, int(std::lround(float(output.height) * render_scale_)));
    if (width != resources_.targets.width() || height != resources_.targets.height()) {
        resources_.targets.resize(width, height);
        for (auto& p : passes_) p->resize(width, height);
    }
    // The sim's weather, once for the frame.
    resources_.lighting.sky.sun_dir = sun_dir_;
    resources_.lighting.set_weather(weather_look(world));

    gather_frame_data(world, data_);

    Camera camera = make_camera(poses.camera, float(output.width) / float(output.height));
    FrameContext frame{world, camera, resources_, output, double(world.tick()) * sim::kTickSeconds, poses, data_};
    timer_->frame_begin();
    for (auto& pass : passes_) {
        gl::DebugGroup group(pass->name());
        auto timing = timer_->scope(pass->name());
        pass->render(frame);
    }
    timer_->frame_end();
}

}  // namespace effects
