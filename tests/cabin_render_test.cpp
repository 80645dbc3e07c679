// The car's cabin from the driver's seat on a real headless context: the rear-view mirror
// shows the view behind (a crate set down behind the car's right shows in the mirror's
// right half, and not once taken away), and the roof lining is lit by the daylight the
// glass lets in (darker under the rain's overcast than on a clear day).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "effects/scene/MirrorPass.h"
#include "effects/scene/WeatherLook.h"
#include "game/capture/ImageFiles.h"
#include "sim/player/CameraRig.h"
#include "sim/vehicle/Car.h"
#include "sim/weather/Weather.h"

namespace {

constexpr int kWidth = 480, kHeight = 270;
const StagePasses kCabinFrame = kLitScene | kMirrorPass | kTonemapPass;

void maybe_write(const game::ImageRGBA8& img, const char* name) {
    if (const char* dir = std::getenv("SPINDRIFT_CABIN_PNG_DIR")) {
        std::filesystem::create_directories(dir);
        game::write_png(std::filesystem::path(dir) / name, img);
    }
}

// The harbour, parked, from the driver's seat; with a large crate 9 m behind the car and
// 2.5 m to its right when `crate_behind`.
game::GameSession harbour_from_the_drivers_seat(bool crate_behind) {
    game::GameSession s = game::GameSession::open("harbour", 1);
    for (int t = 0; t < 10; ++t) {
        sim::TickInput in;
        in.set(sim::Control::Camera, t == 0);
        s.world->step(in);
    }
    if (crate_behind) {
        effects::SceneDesc& scene = s.level.scene;
        const auto crate = std::find_if(scene.models.begin(), scene.models.end(),
                                        [](const effects::Model& m) { return m.name == "crate_large"; });
        EXPECT_NE(crate, scene.models.end());
        const glm::mat4 at = glm::scale(glm::translate(s.world->get<sim::Car>().pose().matrix(), {-9.0f, 0.0f, 2.5f}),
                                        glm::vec3(1.6f));
        scene.props.push_back({int(crate - scene.models.begin()), at});
    }
    return s;
}

double luma(const game::ImageRGBA8& img, int x, int y) {
    const uint8_t* p = &img.pixels[size_t(y * img.width + x) * 4];
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// The mirror's glass on screen: its centre and bounds, in pixels.
struct ScreenBox {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    double centre_x = 0.0;
};
ScreenBox glass_on_screen(RenderStage& stage, const effects::Camera& camera, const game::ImageRGBA8& img) {
    const std::optional<effects::MirrorPass::Glass> g = effects::MirrorPass::find_glass(stage.resources().desc);
    EXPECT_TRUE(g.has_value());
    const glm::mat4 to_clip = camera.view_proj * stage.world().get<sim::Car>().pose().matrix();
    ScreenBox box{img.width, img.height, 0, 0, 0.0};
    auto project = [&](glm::vec3 p, int& x, int& y) {
        const glm::vec4 c = to_clip * glm::vec4(p, 1.0f);
        x = int((c.x / c.w * 0.5f + 0.5f) * float(img.width));
        y = int((0.5f - c.y / c.w * 0.5f) * float(img.height));  // rows from the top
    };
    for (float a : {-1.0f, 1.0f})
        for (float b : {-1.0f, 1.0f}) {
            int x = 0, y = 0;
            project(g->centre + a * g->half_width * g->across + b * g->half_height * g->up, x, y);
            box.x0 = std::min(box.x0, x);
            box.x1 = std::max(box.x1, x);
            box.y0 = std::min(box.y0, y);
            box.y1 = std::max(box.y1, y);
        }
    int cx = 0, cy = 0;
    project(g->centre, cx, cy);
    box.centre_x = cx;
    return box;
}

class CabinRenderTest : public HeadlessTest {};

}  // namespace

TEST_F(CabinRenderTest, MirrorShowsACrateBehindOnItsRightAndNothingOnceItIsGone) {
    RenderStage with(harbour_from_the_drivers_seat(true), {.width = kWidth, .height = kHeight, .passes = kCabinFrame});
    RenderStage without(harbour_from_the_drivers_seat(false), {.width = kWidth, .height = kHeight, .passes = kCabinFrame});
    const effects::Camera camera = with.camera(with.world().get<sim::CameraRig>().view());
    const game::ImageRGBA8 crate = with.render(camera);
    EXPECT_TRUE(with.pass<effects::MirrorPass>().drawn_last_frame());
    const game::ImageRGBA8 empty = without.render(camera);
    const game::ImageRGBA8 no_mirror = without.render(camera, {.skip = kMirrorPass});
    maybe_write(crate, "mirror_crate.png");
    maybe_write(empty, "mirror_empty.png");
    maybe_write(no_mirror, "mirror_off.png");

    const ScreenBox glass = glass_on_screen(with, camera, crate);
    ASSERT_GT(glass.x1 - glass.x0, 20);  // the mirror is on screen, some pixels wide
    ASSERT_GT(glass.y1 - glass.y0, 3);
    int crate_left = 0, crate_right = 0, mirror_outside = 0, mirror_inside = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const bool on_glass = x >= glass.x0 && x <= glass.x1 && y >= glass.y0 && y <= glass.y1;
            const bool crate_shows = std::abs(luma(crate, x, y) - luma(empty, x, y)) > 6.0;
            const bool mirror_shows = std::abs(luma(empty, x, y) - luma(no_mirror, x, y)) > 6.0;
            if (!on_glass) {
                mirror_outside += mirror_shows;
                EXPECT_FALSE(crate_shows) << "the crate shows outside the mirror at " << x << ", " << y;
                continue;
            }
            mirror_inside += mirror_shows;
            (x < glass.centre_x ? crate_left : crate_right) += crate_shows;
        }
    // The picture replaces the sky the glass reflected, and nothing else.
    EXPECT_GT(mirror_inside, (glass.x1 - glass.x0) * (glass.y1 - glass.y0) / 4);
    EXPECT_EQ(mirror_outside, 0);
    // Behind on the right shows on the mirror's right: the picture is flipped as a mirror's.
    EXPECT_GT(crate_right, 8);
    EXPECT_LT(crate_left, crate_right / 4);
}

TEST_F(CabinRenderTest, NoMirrorPictureFromTheChaseCamera) {
    game::GameSession s = game::GameSession::open("harbour", 1);
    s.world->step({});
    RenderStage stage(std::move(s), {.width = kWidth, .height = kHeight, .passes = kCabinFrame});
    stage.render(stage.camera(stage.world().get<sim::CameraRig>().view()));
    EXPECT_FALSE(stage.pass<effects::MirrorPass>().drawn_last_frame());
}

TEST_F(CabinRenderTest, RoofLiningIsDarkerUnderOvercastThanInSunButStillReads) {
    RenderStage stage(harbour_from_the_drivers_seat(false), {.width = kWidth, .height = kHeight, .passes = kCabinFrame});
    const effects::Camera camera = stage.camera(stage.world().get<sim::CameraRig>().view());
    stage.set_weather(effects::WeatherLook{});
    const game::ImageRGBA8 sun = stage.render(camera);
    const std::vector<float> depth = stage.depth();
    stage.set_weather(effects::weather_look(sim::Weather(1.0f)));
    const game::ImageRGBA8 rain = stage.render(camera);
    maybe_write(sun, "lining_sun.png");
    maybe_write(rain, "lining_rain.png");

    // The lining: the top rows, near (window depth 0.95 is 2 m away), off the mirror.
    const ScreenBox glass = glass_on_screen(stage, camera, sun);
    double sun_sum = 0.0, rain_sum = 0.0;
    int pixels = 0;
    for (int y = 0; y < kHeight / 8; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (x >= glass.x0 - 4 && x <= glass.x1 + 4) continue;
            if (depth[size_t(y * kWidth + x)] > 0.95f) continue;
            sun_sum += luma(sun, x, y);
            rain_sum += luma(rain, x, y);
            ++pixels;
        }
    ASSERT_GT(pixels, kWidth * kHeight / 40);
    const double sun_luma = sun_sum / pixels, rain_luma = rain_sum / pixels;
    EXPECT_LT(rain_luma, 0.75 * sun_luma);
    EXPECT_GT(rain_luma, 25.0) << "the lining should still read under cloud";
}
