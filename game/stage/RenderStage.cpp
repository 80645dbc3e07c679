#include "game/stage/RenderStage.h"

#include <glm/geometric.hpp>

#include "game/capture/Readback.h"
#include "sim/player/CameraRig.h"

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
      renderer_(session_.level.scene, *session_.world,
                {.environment_size = options.environment_size,
                 .passes = options.passes,
                 .quality = stage_quality(options)}),
      output_(width_, height_) {
    renderer_.size_scene(width_, height_);
}

effects::Camera RenderStage::camera(const sim::CameraView& view) const {
    return effects::make_camera(view, float(width_) / float(height_));
}

effects::FrameRequest RenderStage::request(const effects::Camera& camera, StageFrame f) const {
    f.camera = camera;
    if (!f.time_s) f.time_s = 0.0;
    if (!f.weather) f.weather = weather_;
    if (!f.sky) f.sky = sky_;
    return f;
}

effects::FrameContext RenderStage::context(const effects::Camera& camera, double time_s) {
    return renderer_.prepare(world(), output_.output(), effects::capture_poses(world()),
                             request(camera, {.time_s = time_s}));
}

void RenderStage::draw(const effects::Camera& camera, const StageFrame& f) {
    renderer_.render(world(), output_.output(), effects::capture_poses(world()), request(camera, f));
}

void RenderStage::draw_as_game(StageFrame f) {
    const sim::World& w = world();
    if (!f.time_s) f.time_s = double(w.tick()) * sim::kTickSeconds;
    draw(camera(w.get<sim::CameraRig>().view()), f);
}

effects::SkyState RenderStage::sky() const {
    if (sky_) return *sky_;
    const sim::World& w = *session_.world;
    return effects::sky_under(weather_ ? *weather_ : effects::weather_look(w), glm::normalize(w.level().sun_direction));
}

ImageRGBA32F RenderStage::hdr() const {
    return read_framebuffer_rgba32f(renderer_.targets().hdr().id(), GL_COLOR_ATTACHMENT0, width_, height_);
}

std::vector<float> RenderStage::depth() const { return read_depth(renderer_.targets().hdr().id(), width_, height_); }

}  // namespace game
