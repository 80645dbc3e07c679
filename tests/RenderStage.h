#pragma once
// The render tests' stage: game::RenderStage (game/stage/RenderStage.h), with the passes
// named once here and every frame checked for GL errors.
#include <gtest/gtest.h>

#include "game/stage/RenderStage.h"

using StagePasses = effects::PassSet;
using game::StageFrame;
using game::StageOptions;

inline const StagePasses kEnvironmentPass = StagePasses::of({"environment"});
inline const StagePasses kShadowPass = StagePasses::of({"shadow"});
inline const StagePasses kSkyOcclusionPass = StagePasses::of({"sky occlusion"});
inline const StagePasses kOpaquePass = StagePasses::of({"opaque"});
inline const StagePasses kDustPass = StagePasses::of({"dust"});
inline const StagePasses kSceneCopyPass = StagePasses::of({"scene_copy"});
inline const StagePasses kWaterPass = StagePasses::of({"water"});
inline const StagePasses kFluidPass = StagePasses::of({"fluid"});
inline const StagePasses kEnergyPass = StagePasses::of({"energy"});
inline const StagePasses kRainStreakPass = StagePasses::of({"rain_streaks"});
inline const StagePasses kRainPass = StagePasses::of({"rain"});
inline const StagePasses kTonemapPass = StagePasses::of({"tonemap"});
inline const StagePasses kFxaaPass = StagePasses::of({"fxaa"});
inline const StagePasses kUpscalePass = StagePasses::of({"upscale"});
inline const StagePasses kMirrorPass = StagePasses::of({"mirror"});
// The lit opaque scene: sky, shadows and sky occlusion for the terrain and props.
inline const StagePasses kLitScene = kEnvironmentPass | kShadowPass | kSkyOcclusionPass | kOpaquePass;
inline const StagePasses kEveryPass = StagePasses::all();

class RenderStage : public game::RenderStage {
public:
    using game::RenderStage::RenderStage;

    void draw(const effects::Camera& camera, const StageFrame& f = {}) {
        game::RenderStage::draw(camera, f);
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
    game::ImageRGBA8 render(const effects::Camera& camera, const StageFrame& f = {}) {
        draw(camera, f);
        return ldr();
    }
    game::ImageRGBA8 render(const sim::CameraView& view, const StageFrame& f = {}) { return render(camera(view), f); }
    game::ImageRGBA8 render_as_game(const StageFrame& f = {}) {
        game::RenderStage::draw_as_game(f);
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        return ldr();
    }
};
