#include "game/stage/RenderStage.h"

#include <glm/geometric.hpp>

#include "game/capture/Readback.h"

namespace game {

effects::QualitySettings stage_quality(const StageOptions& options) {
    effects::QualitySettings q = effects::quality_settings(effects::Quality::High);
    q.shadow_map_size = options.shadow_map_size;
    q.antialias = false;
    return q;
}

RenderStage::RenderStage(std::string_view level_name, StageOptions options)
    : RenderStage(GameSession::open(level_name, 1), options) {}

RenderStage::RenderStage(const sim::LevelDesc& level, StageOptions options)
    : RenderStage(GameSession{LoadedLevel{}, std::make_unique<sim::World>(level)}, options) {}

RenderStage::RenderStage(GameSession session, StageOptions options)
    : width_(options.width),
      height_(options.height),
      session_(std::move(session)),
      scene_{session_.level.scene, effects::SceneGeometry(session_.level.scene, session_.world->terrain()),
             effects::SceneLighting(options.environment_size, options.shadow_map_size), effects::SceneTargets{},
             stage_quality(options)},
      output_(width_, height_) {
    // The level's sun, as the game's renderer sets it; its radiance and the sky's stay
    // at their clear-day defaults (the renderer sets the weather's; a caller may too).
    scene_.lighting.sky.sun_dir = glm::normalize(session_.world->level().sun_direction);
    scene_.targets.resize(width_, height_);
    std::vector<std::unique_ptr<effects::Pass>> made = effects::make_passes(options.passes);
    size_t next = 0;
    for (size_t i = 0; i < effects::pass_table().size(); ++i)
        if (options.passes.contains(i)) passes_.push_back({i, std::move(made[next++])});
}

effects::Camera RenderStage::camera(const sim::CameraView& view) const {
    return effects::make_camera(view, float(width_) / float(height_));
}

effects::FrameContext RenderStage::context(const effects::Camera& camera, double time_s) {
    effects::gather_frame_data(world(), data_);
    return {world(), camera, scene_, output_.output(), time_s, effects::capture_poses(world()), data_};
}

void RenderStage::draw(const effects::Camera& camera, const StageFrame& f) {
    const effects::FrameContext frame = context(camera, f.time_s);
    for (auto& [index, pass] : passes_) {
        if (f.skip.contains(index)) continue;
        if (f.replaced.contains(index)) f.replacement(frame);
        else pass->render(frame);
    }
}

ImageRGBA32F RenderStage::hdr() const {
    return read_framebuffer_rgba32f(scene_.targets.scene().id(), GL_COLOR_ATTACHMENT0, width_, height_);
}

std::vector<float> RenderStage::depth() const { return read_depth(scene_.targets.scene().id(), width_, height_); }

}  // namespace game
