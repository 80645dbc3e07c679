// The weather's look on a real headless context, over the harbour from the chase camera:
// under the sim's full rain the sky is darker and greyer and the ground darker than on a
// clear day, and the rain streaks are drawn only while it rains.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "effects/rain/RainStreakPass.h"
#include "effects/scene/WeatherLook.h"
#include "sim/player/CameraRig.h"
#include "sim/weather/Weather.h"

namespace {

constexpr int kWidth = 320, kHeight = 180;
const StagePasses kWeatherFrame = kLitScene | kRainStreakPass | kTonemapPass;

// Mean luma and saturation ((max - min) / max) of the sky's or the ground's pixels.
struct Region {
    double luma = 0.0, saturation = 0.0;
    int pixels = 0;
};
Region region(const game::ImageRGBA8& img, const std::vector<float>& depth, bool sky) {
    Region r;
    for (int i = 0; i < img.width * img.height; ++i) {
        if ((depth[size_t(i)] >= 1.0f) != sky) continue;
        const uint8_t* p = &img.pixels[size_t(i) * 4];
        const double hi = std::max({p[0], p[1], p[2]}), lo = std::min({p[0], p[1], p[2]});
        r.luma += (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0;
        r.saturation += hi > 0.0 ? (hi - lo) / hi : 0.0;
        ++r.pixels;
    }
    if (r.pixels > 0) {
        r.luma /= r.pixels;
        r.saturation /= r.pixels;
    }
    return r;
}

class WeatherRenderTest : public HeadlessTest {};

}  // namespace

TEST_F(WeatherRenderTest, FullRainGreysAndDarkensTheSkyAndTheGroundAndDrawsStreaks) {
    RenderStage stage("harbour", {.width = kWidth, .height = kHeight, .passes = kWeatherFrame});
    stage.world().step({});  // the chase camera behind the car on the road
    const effects::Camera camera = stage.camera(stage.world().get<sim::CameraRig>().view());

    stage.set_weather(effects::WeatherLook{});
    const game::ImageRGBA8 clear = stage.render(camera);
    const std::vector<float> depth = stage.depth();
    EXPECT_EQ(stage.pass<effects::RainStreakPass>().drawn_last_frame(), 0);

    stage.set_weather(effects::weather_look(sim::Weather(1.0f)));
    const game::ImageRGBA8 rain = stage.render(camera);
    EXPECT_GT(stage.pass<effects::RainStreakPass>().drawn_last_frame(), 1000);

    const Region clear_sky = region(clear, depth, true), rain_sky = region(rain, depth, true);
    const Region clear_ground = region(clear, depth, false), rain_ground = region(rain, depth, false);
    ASSERT_GT(clear_sky.pixels, kWidth * kHeight / 20);  // the view holds both
    ASSERT_GT(clear_ground.pixels, kWidth * kHeight / 4);
    EXPECT_LT(rain_sky.luma, 0.9 * clear_sky.luma);
    EXPECT_LT(rain_sky.saturation, 0.5 * clear_sky.saturation);
    EXPECT_LT(rain_ground.luma, 0.8 * clear_ground.luma);

    // The streaks alone: the same overcast frame without them differs in few pixels.
    const game::ImageRGBA8 no_streaks = stage.render(camera, {.skip = kRainStreakPass});
    int changed = 0;
    for (size_t i = 0; i < rain.pixels.size(); i += 4)
        if (rain.pixels[i] != no_streaks.pixels[i] || rain.pixels[i + 1] != no_streaks.pixels[i + 1]) ++changed;
    EXPECT_GT(changed, 200);
    EXPECT_LT(changed, kWidth * kHeight / 4);  // rain, not a veil over everything
}
