#pragma once
// The render tests' stage: a level's world and scene resources, the passes a test
// picks from the game's frame (run in the order of effects/PassList.cpp), an LDR
// output, and a camera of the test's choosing. A pass added to the game's frame shows
// up here for the tests that ask for it, and in no other test's pixels.
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "effects/Renderer.h"
#include "effects/dust/DustPass.h"
#include "effects/energy/EnergyLightPass.h"
#include "effects/energy/EnergyPass.h"
#include "effects/fluid/FluidPass.h"
#include "effects/rain/RainPass.h"
#include "effects/rain/RainStreakPass.h"
#include "effects/scene/EnvironmentPass.h"
#include "effects/scene/FxaaPass.h"
#include "effects/scene/MirrorPass.h"
#include "effects/scene/OpaquePass.h"
#include "effects/scene/SceneCopyPass.h"
#include "effects/scene/ShadowPass.h"
#include "effects/scene/SkyOcclusionPass.h"
#include "effects/scene/TonemapPass.h"
#include "effects/scene/UpscalePass.h"
#include "effects/water/WaterPass.h"
#include "game/capture/FrameCapture.h"
#include "game/capture/Readback.h"
#include "game/session/GameSession.h"

// The passes of the game's frame, one bit each.
enum StagePass : unsigned {
    kEnvironmentPass = 1u << 0,
    kShadowPass = 1u << 1,
    kSkyOcclusionPass = 1u << 2,
    kEnergyLightPass = 1u << 3,
    kOpaquePass = 1u << 4,
    kDustPass = 1u << 5,
    kSceneCopyPass = 1u << 6,
    kWaterPass = 1u << 7,
    kFluidPass = 1u << 8,
    kEnergyPass = 1u << 9,
    kRainStreakPass = 1u << 10,
    kRainPass = 1u << 11,
    kTonemapPass = 1u << 12,
    kUpscalePass = 1u << 13,
    kFxaaPass = 1u << 14,
    kMirrorPass = 1u << 15,
};
using StagePasses = unsigned;
// The lit opaque scene: sky, shadows and sky occlusion for the terrain and props.
constexpr StagePasses kLitScene = kEnvironmentPass | kShadowPass | kSkyOcclusionPass | kOpaquePass;
constexpr StagePasses kEveryPass = (kMirrorPass << 1) - 1;

// Which bit a pass of effects::make_pass_list() is: a pass the stage does not know
// yet is an error, not a pass silently left out.
inline StagePass stage_pass_of(const effects::Pass& p) {
    if (dynamic_cast<const effects::EnvironmentPass*>(&p)) return kEnvironmentPass;
    if (dynamic_cast<const effects::ShadowPass*>(&p)) return kShadowPass;
    if (dynamic_cast<const effects::SkyOcclusionPass*>(&p)) return kSkyOcclusionPass;
    if (dynamic_cast<const effects::EnergyLightPass*>(&p)) return kEnergyLightPass;
    if (dynamic_cast<const effects::OpaquePass*>(&p)) return kOpaquePass;
    if (dynamic_cast<const effects::DustPass*>(&p)) return kDustPass;
    if (dynamic_cast<const effects::SceneCopyPass*>(&p)) return kSceneCopyPass;
    if (dynamic_cast<const effects::WaterPass*>(&p)) return kWaterPass;
    if (dynamic_cast<const effects::FluidPass*>(&p)) return kFluidPass;
    if (dynamic_cast<const effects::EnergyPass*>(&p)) return kEnergyPass;
    if (dynamic_cast<const effects::RainStreakPass*>(&p)) return kRainStreakPass;
    if (dynamic_cast<const effects::RainPass*>(&p)) return kRainPass;
    if (dynamic_cast<const effects::TonemapPass*>(&p)) return kTonemapPass;
    if (dynamic_cast<const effects::UpscalePass*>(&p)) return kUpscalePass;
    if (dynamic_cast<const effects::FxaaPass*>(&p)) return kFxaaPass;
    if (dynamic_cast<const effects::MirrorPass*>(&p)) return kMirrorPass;
    throw std::logic_error("RenderStage has no bit for the pass \"" + std::string(p.name()) + "\"");
}

struct StageOptions {
    int width = 0, height = 0;
    StagePasses passes = kEveryPass;  // the passes the stage holds
    int environment_size = 32, shadow_map_size = 1024;  // the high preset's shadow map
};

// The high preset, with the stage's shadow map size and without anti-aliasing: an
// effect's test reads its own pixels (the FXAA test turns it on).
inline effects::QualitySettings stage_quality(const StageOptions& options) {
    effects::QualitySettings q = effects::quality_settings(effects::Quality::High);
    q.shadow_map_size = options.shadow_map_size;
    q.antialias = false;
    return q;
}

// What one frame does differently from the stage's default.
struct StageFrame {
    StagePasses skip = 0;  // held passes left out of this frame
    double time_s = 0.0;   // effects::FrameContext::time_s
    // The passes in `replaced` are drawn by `replacement` instead, in their place: a
    // test's own view of the sim (a pass's draw(frame, view)).
    StagePasses replaced = 0;
    std::function<void(const effects::FrameContext&)> replacement;
};

class RenderStage {
public:
    RenderStage(std::string_view level_name, StageOptions options)
        : RenderStage(game::GameSession::open(level_name, 1), options) {}
    // A level made in code: no models, props or dust, only the sim's terrain.
    RenderStage(const sim::LevelDesc& level, StageOptions options)
        : RenderStage(game::GameSession{game::LoadedLevel{}, std::make_unique<sim::World>(level)}, options) {}
    RenderStage(game::GameSession session, StageOptions options)
        : width_(options.width),
          height_(options.height),
          session_(std::move(session)),
          scene_{session_.level.scene, effects::SceneGeometry(session_.level.scene, session_.world->terrain()),
                 effects::SceneLighting(options.environment_size, options.shadow_map_size), effects::SceneTargets{},
                 stage_quality(options)},
          output_(width_, height_) {
        // The level's sun, as the game's renderer sets it; its radiance and the sky's stay
        // at their clear-day defaults (the renderer sets the weather's; a test may too).
        scene_.lighting.sky.sun_dir = glm::normalize(session_.world->level().sun_direction);
        scene_.targets.resize(width_, height_);
        // The game's list is the one place that knows the order: the passes not held are
        // made and dropped here.
        for (auto& p : effects::make_pass_list()) {
            const StagePass kind = stage_pass_of(*p);
            if (options.passes & kind) passes_.push_back({kind, std::move(p)});
        }
    }
    RenderStage(const RenderStage&) = delete;  // scene_ refers into session_
    RenderStage& operator=(const RenderStage&) = delete;

    effects::Camera camera(const sim::CameraView& view) const {
        return effects::make_camera(view, float(width_) / float(height_));
    }
    effects::FrameContext context(const effects::Camera& camera, double time_s = 0.0) {
        return {world(), camera, scene_, output_.output(), time_s, effects::capture_poses(world())};
    }

    // Runs the held passes, less the frame's skipped ones, in the game's order.
    void draw(const effects::Camera& camera, const StageFrame& f = {}) {
        const effects::FrameContext frame = context(camera, f.time_s);
        for (auto& [kind, pass] : passes_) {
            if (f.skip & kind) continue;
            if (f.replaced & kind) f.replacement(frame);
            else pass->render(frame);
        }
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
    game::ImageRGBA8 render(const effects::Camera& camera, const StageFrame& f = {}) {
        draw(camera, f);
        return ldr();
    }
    game::ImageRGBA8 render(const sim::CameraView& view, const StageFrame& f = {}) { return render(camera(view), f); }

    // The last frame's output (after the tonemap), scene colour (HDR) and window depth.
    game::ImageRGBA8 ldr() const { return output_.read(); }
    game::ImageRGBA32F hdr() const {
        return game::read_framebuffer_rgba32f(scene_.targets.scene().id(), GL_COLOR_ATTACHMENT0, width_, height_);
    }
    std::vector<float> depth() const { return game::read_depth(scene_.targets.scene().id(), width_, height_); }

    // A held pass, for tests that tweak its look or read what it drew.
    template <class P>
    P& pass() {
        for (auto& held : passes_)
            if (auto* typed = dynamic_cast<P*>(held.pass.get())) return *typed;
        throw std::logic_error("the stage does not hold that pass");
    }
    sim::World& world() { return *session_.world; }
    effects::SceneResources& scene() { return scene_; }

private:
    int width_, height_;
    game::GameSession session_;
    effects::SceneResources scene_;
    struct HeldPass {
        StagePass kind;
        std::unique_ptr<effects::Pass> pass;
    };
    std::vector<HeldPass> passes_;  // in the game's order
    game::FrameCapture output_;
};
