// The weather (sim/weather/Weather.h): rain brings cloud and wets the road over time, the
// road dries slowly after, every value stays within 0..1, and the same inputs give the
// same bits. The rain on the glass follows its rain rate.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "SimTestLevel.h"
#include "sim/player/Player.h"
#include "sim/rain/GlassSurface.h"
#include "sim/rain/RainSim.h"
#include "sim/weather/Weather.h"
#include "sim/world/World.h"

using sim::Control;
using sim::Weather;

namespace {

constexpr float kDt = 1.0f / 60.0f;

void run(Weather& w, float rain, float seconds) {
    for (int t = 0; t < int(seconds * 60.0f); ++t) w.advance(rain, kDt);
}

void expect_bounded(const Weather& w) {
    for (float v : {w.rain_rate(), w.cloud_cover(), w.road_wetness(), w.sunlight()}) {
        EXPECT_GE(v, 0.0f);
        EXPECT_LE(v, 1.0f);
    }
}

}  // namespace

TEST(Weather, RainBringsCloudAndWetsTheRoadOverTime) {
    Weather w(0.0f);
    EXPECT_EQ(w.rain_rate(), 0.0f);
    EXPECT_EQ(w.cloud_cover(), 0.0f);
    EXPECT_EQ(w.road_wetness(), 0.0f);
    EXPECT_EQ(w.sunlight(), 1.0f);
    run(w, 1.0f, 0.5f);
    // Not at once: the rain and the cloud build up, the road has barely darkened.
    EXPECT_GT(w.rain_rate(), 0.0f);
    EXPECT_LT(w.rain_rate(), 0.5f);
    EXPECT_GT(w.cloud_cover(), 0.0f);
    EXPECT_LT(w.road_wetness(), 0.1f);
    float last_wet = w.road_wetness(), last_cloud = w.cloud_cover();
    for (int s = 0; s < 20; ++s) {
        run(w, 1.0f, 1.0f);
        EXPECT_GE(w.road_wetness(), last_wet);
        EXPECT_GE(w.cloud_cover(), last_cloud);
        last_wet = w.road_wetness();
        last_cloud = w.cloud_cover();
        expect_bounded(w);
    }
    EXPECT_NEAR(w.rain_rate(), 1.0f, 0.01f);
    EXPECT_NEAR(w.cloud_cover(), 1.0f, 0.01f);
    EXPECT_GT(w.road_wetness(), 0.95f);
    EXPECT_LT(w.sunlight(), 0.3f);
    run(w, 1.0f, 20.0f);
    EXPECT_EQ(w.rain_rate(), 1.0f);  // settled on the target, not creeping towards it
    EXPECT_EQ(w.cloud_cover(), 1.0f);
}

TEST(Weather, AfterTheRainTheSkyClearsAndTheRoadDriesSlowly) {
    Weather w(1.0f);
    EXPECT_EQ(w.cloud_cover(), 1.0f);
    EXPECT_EQ(w.road_wetness(), 1.0f);  // a level that opens in a downpour opens soaked
    run(w, 0.0f, 10.0f);
    EXPECT_LT(w.rain_rate(), 0.05f);
    EXPECT_GT(w.road_wetness(), 0.7f);  // still wet ten seconds on
    EXPECT_LT(w.cloud_cover(), 0.6f);
    run(w, 0.0f, 60.0f);
    EXPECT_EQ(w.rain_rate(), 0.0f);  // stopped, exactly: nothing falls any more
    EXPECT_EQ(w.road_wetness(), 0.0f);
    EXPECT_LT(w.cloud_cover(), 0.01f);
    EXPECT_GT(w.sunlight(), 0.99f);
    expect_bounded(w);
}

TEST(Weather, SettlesWithinBoundsAtEveryIntensity) {
    for (float r : {0.25f, 0.5f, 0.75f}) {
        Weather from_dry(0.0f);
        run(from_dry, r, 120.0f);
        EXPECT_EQ(from_dry.rain_rate(), r);
        EXPECT_NEAR(from_dry.cloud_cover(), Weather::settled_cloud(r), 1e-3f);
        EXPECT_NEAR(from_dry.road_wetness(), Weather::settled_wetness(r), 1e-3f);
        EXPECT_GT(from_dry.road_wetness(), 0.5f) << r;  // even a drizzle wets the road
        Weather settled(r);  // a level opening at r starts where the weather settles
        EXPECT_EQ(settled.cloud_cover(), Weather::settled_cloud(r));
        EXPECT_EQ(settled.road_wetness(), Weather::settled_wetness(r));
        expect_bounded(settled);
    }
    // Out-of-range controls are clamped; a level's bad intensity is refused.
    Weather w(0.5f);
    run(w, 7.0f, 5.0f);
    expect_bounded(w);
    run(w, -3.0f, 5.0f);
    expect_bounded(w);
    EXPECT_THROW(Weather(1.5f), std::invalid_argument);
    EXPECT_THROW(Weather(-0.1f), std::invalid_argument);
    EXPECT_THROW(w.advance(std::numeric_limits<float>::quiet_NaN(), kDt), std::invalid_argument);
}

TEST(Weather, TheWorldStepsItFromThePlayersKeysAndHashesIt) {
    sim::World a(make_test_level()), b(make_test_level());
    auto step = [](sim::World& w, bool rain_up) {
        sim::TickInput in;
        in.set(Control::RainUp, rain_up);
        w.step(in);
    };
    for (int t = 0; t < 240; ++t) {
        step(a, t == 10 || t == 12);  // two presses: half rain
        step(b, t == 10 || t == 12);
    }
    const Weather& wa = a.get<Weather>();
    EXPECT_GT(wa.rain_rate(), 0.4f);  // nearly there after four seconds
    EXPECT_LT(wa.rain_rate(), 0.5f);
    EXPECT_GT(wa.cloud_cover(), 0.5f);
    EXPECT_GT(wa.road_wetness(), 0.1f);
    EXPECT_EQ(a.hash().world, b.hash().world);
    // A different weather alone changes the world's hash, under the name "weather".
    sim::World c(make_test_level());
    for (int t = 0; t < 240; ++t) step(c, t == 10);  // one press: a quarter
    const sim::WorldHash ha = a.hash(), hc = c.hash();
    const std::vector<std::string> names = a.subsystem_names();
    size_t k = size_t(std::find(names.begin(), names.end(), "weather") - names.begin());
    ASSERT_LT(k, names.size());
    EXPECT_NE(ha.parts[k], hc.parts[k]);
    EXPECT_NE(ha.world, hc.world);
}

TEST(Weather, TheGlassGetsTheWeathersRainNotThePlayersSetting) {
    // Full rain set just now falls on the glass as a shower still building: fewer drops
    // than on a glass in a downpour that has settled.
    auto drops_after_half_a_second = [](float start, bool press) {
        sim::LevelDesc level = make_test_level();
        sim::GlassSurface::flat_edges(1.4f, 0.8f, 0.76f, level.rain.glass_lower, level.rain.glass_upper);
        level.rain_intensity = start;
        sim::World w(level);
        for (int t = 0; t < 30; ++t) {
            sim::TickInput in;
            in.set(Control::RainUp, press && t < 8 && t % 2 == 0);  // four presses: full rain
            w.step(in);
        }
        EXPECT_EQ(w.get<sim::Player>().rain_intensity(), 1.0f);
        return w.get<sim::RainSim>().drops().size();
    };
    const size_t settled = drops_after_half_a_second(1.0f, false);
    const size_t building = drops_after_half_a_second(0.0f, true);
    EXPECT_GT(settled, 20u);
    EXPECT_LT(building * 3, settled);
}
