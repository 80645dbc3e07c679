#pragma once
// A stage for drawing some of the frame's passes outside the game's renderer: a level's
// world and scene resources, the passes picked by name (run in the order of
// effects/PassList.cpp), an LDR output, and a camera of the caller's choosing. The
// render tests and the benches draw through it; a pass added to the game's frame shows
// up here for those that ask for it, and in no one else's pixels.
#include <functional>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "effects/PassList.h"
#include "effects/Quality.h"
#include "effects/scene/FrameContext.h"
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

// What one frame does differently from the stage's default.
struct StageFrame {
    effects::PassSet skip;  // held passes left out of this frame
    double time_s = 0.0;    // effects::FrameContext::time_s
    // The passes in `replaced` are drawn by `replacement` instead, in their place: a
    // caller's own view of the sim (a pass's draw(frame, view)).
    effects::PassSet replaced;
    std::function<void(const effects::FrameContext&)> replacement;
};

class RenderStage {
public:
    RenderStage(std::string_view level_name, StageOptions options);
    // A level made in code: no models, props or dust, only the sim's terrain.
    RenderStage(const sim::LevelDesc& level, StageOptions options);
    RenderStage(GameSession session, StageOptions options);
    RenderStage(const RenderStage&) = delete;  // scene_ refers into session_
    RenderStage& operator=(const RenderStage&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    effects::Camera camera(const sim::CameraView& view) const;
    // A frame from `camera` (its data gathered from the world now).
    effects::FrameContext context(const effects::Camera& camera, double time_s = 0.0);

    // Runs the held passes, less the frame's skipped ones, in the game's order.
    void draw(const effects::Camera& camera, const StageFrame& f = {});

    // The last frame's output (after the tonemap), scene colour (HDR) and window depth.
    ImageRGBA8 ldr() const { return output_.read(); }
    ImageRGBA32F hdr() const;
    std::vector<float> depth() const;

    // A held pass, for callers that tweak its look or read what it drew.
    template <class P>
    P& pass() {
        for (auto& held : passes_)
            if (auto* typed = dynamic_cast<P*>(held.pass.get())) return *typed;
        throw std::logic_error("the stage does not hold that pass");
    }
    sim::World& world() { return *session_.world; }
    effects::SceneResources& scene() { return scene_; }
    const FrameCapture& output() const { return output_; }

private:
    int width_, height_;
    GameSession session_;
    effects::SceneResources scene_;
    effects::FrameData data_;
    struct HeldPass {
        size_t index;  // in the pass table
        std::unique_ptr<effects::Pass> pass;
    };
    std::vector<HeldPass> passes_;  // in the game's order
    FrameCapture output_;
};

}  // namespace game
