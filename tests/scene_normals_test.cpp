// The scene's normals target is drawn only when asked (SceneTargets::write_normals):
// off, the picture is the same to the bit and an EXR capture refuses; on, every drawn
// pixel holds a unit world normal, the sky none, and the capture writes.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "LevelFiles.h"
#include "RenderStage.h"
#include "effects/scene/FramePoses.h"
#include "game/capture/CaptureError.h"
#include "game/capture/Readback.h"

namespace {

constexpr int W = 160, H = 90;

class SceneNormalsTest : public HeadlessTest {};

TEST_F(SceneNormalsTest, DrawnOnlyWhenAskedAndThePictureIsTheSameEitherWay) {
    RenderStage stage("harbour", {.width = W, .height = H, .passes = kLitScene | kTonemapPass});
    const sim::CameraView view = effects::capture_poses(stage.world()).camera;  // the chase camera: car, road, sky
    effects::SceneTargets& targets = stage.targets();
    level_files::TempDir dir("scene_normals");

    ASSERT_FALSE(targets.writes_normals()) << "off unless asked";
    stage.render(view);
    const game::ImageRGBA32F without = stage.hdr();
    EXPECT_THROW(game::FrameCapture::write_scene_exr(dir.path / "off.exr", targets, 0.1f, 4000.0f), game::CaptureError);
    EXPECT_FALSE(std::filesystem::exists(dir.path / "off.exr"));

    targets.write_normals(true);
    stage.render(view);
    const game::ImageRGBA32F with = stage.hdr();
    EXPECT_EQ(with.pixels, without.pixels) << "the normals change nothing in the picture";

    const game::ImageRGBA32F normals = game::read_framebuffer_rgba32f(targets.hdr().id(), GL_COLOR_ATTACHMENT1, W, H);
    const std::vector<float> depth = stage.depth();
    int drawn = 0, sky = 0, bad = 0;
    for (size_t i = 0; i < size_t(W * H); ++i) {
        const float* n = &normals.pixels[i * 4];
        const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (depth[i] < 1.0f) {
            ++drawn;
            if (std::fabs(length - 1.0f) > 0.01f) ++bad;
        } else {
            ++sky;
            if (length != 0.0f) ++bad;
        }
    }
    EXPECT_GT(drawn, W * H / 4);
    EXPECT_GT(sky, W * H / 50);
    EXPECT_EQ(bad, 0) << "of " << drawn << " drawn and " << sky << " sky pixels";
    game::FrameCapture::write_scene_exr(dir.path / "on.exr", targets, 0.1f, 4000.0f);
    EXPECT_TRUE(std::filesystem::exists(dir.path / "on.exr"));

    targets.write_normals(false);
    stage.render(view);
    EXPECT_EQ(stage.hdr().pixels, without.pixels);
}

}  // namespace
