#pragma once
// A stage for drawing some of the frame's passes outside the game's loop: a level's
// session, a renderer holding the passes picked by name (run in the order of
// effects/PassList.cpp, as the game runs them), an LDR output, and a camera of the
// caller's choosing. The render tests and the benches draw through it; a pass added to
// the game's frame shows up here for those that ask for it, and in no one else's pixels.
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "effects/Renderer.h"
#include "game/capture/FrameCapture.h"
#include "game/session/GameSession.h"

namespace game {

struct StageOptions {
    int width = 0, height = 0;
    effects::PassSet passes = effects::PassSet::all();  // the passes the stage holds
    int environment_size = 32, shadow_map_size = 1024;  // the high preset's shadow map
};

// The high preset, with the stage's shadow map size and without anti-aliasing: an
// effect's test reads its own pixels (the FXAA test turns it on).
effects::QualitySettings stage_quality(const StageOptions& options);

// What one frame does differently from the stage's default (its camera is the caller's).
using StageFrame = effects::FrameRequest;

class RenderStage {
public:
    RenderStage(std::string_view level_name, StageOptions options);
    // A level made in code: no models, props or dust, only the sim's terrain.
    RenderStage(const sim::LevelDesc& level, StageOptions options);
    RenderStage(GameSession session, StageOptions options);
    RenderStage(const RenderStage&) = delete;  // the renderer refers into session_
    RenderStage& operator=(const RenderStage&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    effects::Camera camera(const sim::CameraView& view) const;
    // A frame from `camera`, its data gathered from the world now, no pass run: for a
    // caller that draws a pass's own view (valid until the next frame).
    effects::FrameContext context(const effects::Camera& camera, double time_s = 0.0);

    // Runs the held passes, less the frame's skipped ones, through the renderer.
    void draw(const effects::Camera& camera, const StageFrame& f = {});
    // The same as the game draws it: from the world's camera, at the world's time unless
    // the frame says otherwise.
    void draw_as_game(StageFrame f = {});

    // The weather every frame is drawn under, instead of the world's (none: the world's).
    void set_weather(std::optional<effects::WeatherLook> weather) { weather_ = weather; }
    // The sky every frame is drawn under, instead of the sky under the weather.
    void set_sky(std::optional<effects::SkyState> sky) { sky_ = sky; }
    // The sky the next frame is drawn under.
    effects::SkyState sky() const;

    // The last frame's output (after the tonemap), scene colour (HDR) and window depth.
    ImageRGBA8 ldr() const { return output_.read(); }
    ImageRGBA32F hdr() const;
    std::vector<float> depth() const;

    // A held pass, for callers that tweak its look or read what it drew.
    template <class P>
    P& pass() {
        for (auto& held : renderer_.passes())
            if (auto* typed = dynamic_cast<P*>(held.get())) return *typed;
        throw std::logic_error("the stage does not hold that pass");
    }
    sim::World& world() { return *session_.world; }
    effects::RenderResources& resources() { return renderer_.resources(); }
    effects::SceneTargets& targets() { return renderer_.targets(); }
    effects::SceneLighting& lighting() { return renderer_.lighting(); }
    effects::Renderer& renderer() { return renderer_; }
    const FrameCapture& output() const { return output_; }

private:
    effects::FrameRequest request(const effects::Camera& camera, StageFrame f) const;

    int width_, height_;
    GameSession session_;
    effects::Renderer renderer_;
    FrameCapture output_;
    std::optional<effects::WeatherLook> weather_;
    std::optional<effects::SkyState> sky_;
};

}  // namespace game
