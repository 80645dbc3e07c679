#include "effects/Renderer.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "effects/gl/DebugGroup.h"
#include "effects/scene/TemporalPass.h"

namespace effects {

Renderer::Renderer(const SceneDesc& scene, const sim::World& world, RendererOptions options)
    : resources_{scene, SceneGeometry(scene, world.terrain()), options.quality},
      lighting_(options.environment_size, options.quality.shadow_map_size),
      passes_(make_passes(options.passes)),
      timer_(std::make_unique<gl::PassTimer>(options.timing)),
      sun_dir_(glm::normalize(world.level().sun_direction)),
      sky_occlusion_view_proj_(
          sky_occlusion_view_proj(resources_.geometry.props_min(), resources_.geometry.props_max())) {
    for (size_t i = 0; i < pass_table().size(); ++i)
        if (options.passes.contains(i)) pass_indices_.push_back(i);
    params_.add("tonemap", "exposure", &resources_.exposure, 0.1f, 4.0f);
    params_.add("shadow", "half extent (m)", &shadow_framing_.half_extent_m, 20.0f, 200.0f);
    params_.add("shadow", "centre ahead (m)", &shadow_framing_.ahead_m, 0.0f, 100.0f);
    params_.add("energy", "light per strength", &beam_lighting_.intensity_per_strength, 0.0f, 400.0f);
    params_.add("energy", "light reach m", &beam_lighting_.reach_m, 1.0f, 40.0f);
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

void Renderer::size_scene(int output_width, int output_height) {
    const int width = std::max(1, int(std::lround(float(output_width) * render_scale_)));
    const int height = std::max(1, int(std::lround(float(output_height) * render_scale_)));
    if (width != targets_.width() || height != targets_.height()) {
        targets_.resize(width, height);
        for (auto& p : passes_) p->resize(width, height);
    }
}

FrameContext Renderer::prepare(const sim::World& world, RenderOutput output, const FramePoses& poses,
                               const FrameRequest& request) {
    size_scene(output.width, output.height);
    camera_ = request.camera ? *request.camera : make_camera(poses.camera, float(output.width) / float(output.height));
    if (resources_.quality.temporal) {
        const glm::vec2 px = temporal_jitter_px(temporal_frame_++, scene_scale(targets_, output));
        camera_ = jittered(camera_, 2.0f * px / glm::vec2(targets_.width(), targets_.height()));
    }
    // The ground's detail for this frame's eye and scene pixels, for every pass to draw.
    resources_.geometry.plan_terrain(camera_.eye, 0.5f * camera_.proj[1][1] * float(targets_.height()));
    gather_frame_data(world,
                      {.camera = camera_,
                       .sun_dir = sun_dir_,
                       .shadow_map_size = resources_.quality.shadow_map_size,
                       .shadow_framing = shadow_framing_,
                       .sky_occlusion_view_proj = sky_occlusion_view_proj_,
                       .beam_lighting = beam_lighting_,
                       .weather = request.weather,
                       .sky = request.sky,
                       .energy = request.energy},
                      data_);
    // Once, for every lit pass to bind (SceneLighting::apply).
    lighting_.set_line_lights(data_.line_lights);
    const double time_s = request.time_s ? *request.time_s : double(world.tick()) * sim::kTickSeconds;
    return {world, camera_, resources_, lighting_, targets_, output, time_s, poses, data_};
}

void Renderer::render(const sim::World& world, RenderOutput output) { render(world, output, capture_poses(world)); }

void Renderer::render(const sim::World& world, RenderOutput output, const FramePoses& poses,
                      const FrameRequest& request) {
    const FrameContext frame = prepare(world, output, poses, request);
    timer_->frame_begin();
    pass_draws_.clear();
    try {
        for (size_t i = 0; i < passes_.size(); ++i) {
            const size_t index = pass_indices_[i];
            if (request.skip.contains(index)) continue;
            Pass& pass = *passes_[i];
            gl::DebugGroup group(pass.name());
            const gl::DrawCount before = gl::draw_count();
            {
                auto timing = timer_->scope(pass.name());
                if (request.replaced.contains(index)) request.replacement(frame);
                else pass.render(frame);
            }
            const gl::DrawCount after = gl::draw_count();
            if (after.draws != before.draws)
                pass_draws_.push_back({std::string(pass.name()),
                                       {after.draws - before.draws, after.triangles - before.triangles}});
        }
    } catch (...) {
        timer_->frame_end();  // a pass refused its input: the next frame starts afresh
        throw;
    }
    timer_->frame_end();
}

}  // namespace effects
