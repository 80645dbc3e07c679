#include "effects/rain/RainStreakPass.h"

#include <algorithm>
#include <cmath>

#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/PipelineState.h"

namespace effects {
namespace {

// The drops' fall (m/s) with a little wind across it: a slant reads as rain, not snow.
const glm::vec3 kFall(1.2f, -9.0f, 0.6f);

// The streaks' colour under a clear sky's intensity: sky.glsl's cloud deck overhead,
// a little brighter (drops scatter the light towards the eye).
const glm::vec3 kStreakColour(0.70f, 0.73f, 0.77f);

}  // namespace

RainStreakPass::RainStreakPass()
    : program_(gl::Program::from_files("rain_streaks", {"rain/streaks.vert.glsl", "rain/streaks.frag.glsl"})) {}

void RainStreakPass::register_params(ParamRegistry& params) {
    params.add("rain streaks", "enabled", &look_.enabled);
    params.add("rain streaks", "drops at full rain", &look_.drops_at_full_rain, 0, 40000);
    params.add("rain streaks", "box m", &look_.box_m, 8.0f, 60.0f);
    params.add("rain streaks", "near m", &look_.near_m, 0.5f, 6.0f);
    params.add("rain streaks", "opacity", &look_.opacity, 0.0f, 1.0f);
    params.add("rain streaks", "exposure s", &look_.exposure_s, 0.005f, 0.1f);
}

void RainStreakPass::render(const FrameContext& frame) {
    const WeatherLook& weather = frame.data.weather;
    drawn_ = look_.enabled ? int(std::lround(float(look_.drops_at_full_rain) * std::clamp(weather.rain_rate, 0.0f, 1.0f))) : 0;
    if (drawn_ <= 0) return;
    const SceneTargets& t = frame.targets;
    if (generation_ != t.generation()) {
        fbo_ = gl::Framebuffer::create("rain_streaks");
        fbo_.attach_colour(0, t.colour());
        fbo_.attach_depth(t.depth());
        fbo_.check_complete();
        generation_ = t.generation();
    }
    fbo_.bind();
    glViewport(0, 0, t.width(), t.height());
    gl::PipelineScope state({.depth_test = true, .blend = gl::kAlphaOver});
    program_.use();
    program_.set("u_view_proj", frame.camera.view_proj);
    program_.set("u_eye", frame.camera.eye);
    // Wrapped to a period the box repeats in, so the time stays small and exact.
    program_.set("u_time_s", float(std::fmod(frame.time_s, 600.0)));
    program_.set("u_box_m", glm::vec3(look_.box_m, 0.5f * look_.box_m, look_.box_m));
    program_.set("u_fall_mps", kFall);
    program_.set("u_exposure_s", look_.exposure_s);
    program_.set("u_near_m", look_.near_m);
    program_.set("u_opacity", look_.opacity);
    program_.set("u_colour", kStreakColour * weather.sky_intensity);
    gl::bind_empty_vertex_array();
    glDrawArrays(GL_LINES, 0, 2 * drawn_);
}

}  // namespace effects
