// White water where a splash falls back (effects/water/SplashFoam): the foam follows the
// sheets' vertices to where they land, appears there when they do, spreads and fades
// over a few seconds, and is a function of the ticks (forgotten when the world is
// restored). On harbour_boat's first stone, seen from above: the foam around the splash
// rises after the crown and the jet fall back, then fades. Set SPINDRIFT_WATER_PNG_DIR
// to write the frames as PNGs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "SimTestLevel.h"
#include "effects/water/SplashFoam.h"
#include "effects/water/WaterPass.h"
#include "effects/water/WaterView.h"
#include "game/capture/ImageFiles.h"
#include "sim/objects/ThrownObjects.h"
#include "sim/water/WaterSim.h"
#include "sim/world/World.h"

namespace {

// One vertex thrown up and out from (0, 0) at tick 0, in a 2x2 sheet (the other three
// stay under the water), as the sim would show it at `tick`: stepped like
// sim::SplashSheet::step (v -= g dt, then p += v dt).
struct OneDrop {
    std::vector<glm::vec3> positions = std::vector<glm::vec3>(4, glm::vec3(0.0f, -0.1f, 0.0f));
    std::vector<glm::vec3> velocities = std::vector<glm::vec3>(4, glm::vec3(0.0f));
    std::vector<uint8_t> airborne = std::vector<uint8_t>(4, 0);

    effects::WaterView at(int64_t tick, uint64_t restore_generation = 0) {
        const float dt = 1.0f / 60.0f, g = 9.81f;
        glm::vec3 p(0.0f), v(1.0f, 3.0f, 0.0f);
        bool up = true;
        for (int64_t t = 0; t < tick && up; ++t) {
            v.y -= g * dt;
            p += v * dt;
            up = !(v.y < 0.0f && p.y < 0.0f);
        }
        positions[0] = p;
        velocities[0] = up ? v : glm::vec3(0.0f);
        airborne[0] = up ? 1 : 0;
        effects::WaterView view;
        view.tick = tick;
        view.tick_s = dt;
        view.restore_generation = restore_generation;
        if (up) view.sheets.push_back({2, 0.04f, positions, airborne, glm::vec2(0.0f), velocities, 0, g});
        return view;
    }
};

// 3 m/s up lands after 2 * 3 / 9.81 s, on the 36th tick (stepped), 0.6 m out.
constexpr int64_t kLanding = 36;

}  // namespace

TEST(SplashFoam, ALandingLeavesFoamThatSpreadsAndFades) {
    effects::SplashFoam foam;
    const effects::FoamLook look;
    OneDrop drop;
    foam.update(drop.at(5), look);
    EXPECT_EQ(foam.field().size, 0) << "no foam before anything has landed";
    foam.update(drop.at(kLanding - 1), look);
    EXPECT_EQ(foam.field().size, 0) << "no foam before anything has landed";
    foam.update(drop.at(kLanding), look);
    ASSERT_GT(foam.field().size, 0) << "foam where the vertex landed, from the tick it lands";
    const float fresh = foam.field().at({0.6f, 0.0f});
    EXPECT_GT(fresh, 0.1f) << "foam where the vertex lands";
    EXPECT_EQ(foam.field().at({-0.6f, 0.0f}), 0.0f) << "and none where it did not";

    // A second later it has spread wider and thinner.
    foam.update(drop.at(kLanding + 60), look);
    const float later = foam.field().at({0.6f, 0.0f});
    EXPECT_LT(later, 0.5f * fresh) << "the foam fades";
    EXPECT_GT(foam.field().at({0.6f + 0.2f, 0.0f}), 0.0f) << "the foam spreads beyond where it landed";
    // After its life it is gone.
    foam.update(drop.at(kLanding + 60 * 6), look);
    EXPECT_EQ(foam.field().size, 0) << "the foam is gone after " << look.life_s << " s";
}

TEST(SplashFoam, IsAFunctionOfTheTicksAndForgottenOnRestore) {
    const effects::FoamLook look;
    // Seen on every tick of the flight, or once: the same foam.
    effects::SplashFoam every, once;
    OneDrop a, b;
    for (int64_t t = 1; t <= kLanding + 20; ++t) every.update(a.at(t), look);
    once.update(b.at(10), look);
    once.update(b.at(kLanding + 20), look);
    ASSERT_GT(every.field().size, 0);
    EXPECT_EQ(every.field().texels, once.field().texels) << "a vertex seen in the air on many frames lands once";
    EXPECT_EQ(every.live_landings(), 1u);

    // The world replaced by a snapshot: what was seen before is forgotten.
    once.update(b.at(kLanding + 21, 1), look);
    EXPECT_EQ(once.field().size, 0) << "a restored world starts without foam";
    // The tick going back (a seek) forgets it too.
    every.update(a.at(20), look);
    EXPECT_EQ(every.field().size, 0) << "going back in time starts without foam";
}

namespace {

void maybe_write_png(const std::string& name, const game::ImageRGBA8& img) {
    if (const char* dir = std::getenv("SPINDRIFT_WATER_PNG_DIR"))
        game::write_png(std::filesystem::path(dir) / (name + ".png"), img);
}

constexpr int kWidth = 320, kHeight = 180;
const glm::vec3 kDropPoint{10.0f, 1.2f, 12.0f};  // over open water, 12 m off the test level's shore
const StagePasses kWaterFrame = kLitScene | kSceneCopyPass | kWaterPass | kTonemapPass;

struct Coverage {
    double white = 0.0;   // share of the sea pixels around the splash that are foam white
    double radius_m = 0.0;  // mean distance of those from the splash
};

}  // namespace

// A heavy stone dropped into calm water, seen from 6 m up on every few ticks: white
// water around the splash must rise after the crown and the jet fall back, spread, and
// fade again within a few seconds. (harbour_boat's first stone would do, but its boat
// drives over the spot two seconds after the splash.)
class SplashFoamRender : public HeadlessTest {
protected:
    void TearDown() override { stage_.reset(); }

    // White pixels of the sea within `radius` of the splash.
    Coverage coverage(const game::ImageRGBA8& img, const std::vector<float>& depth, const effects::Camera& cam,
                      float sea_level, float radius) const {
        Coverage c;
        size_t sea = 0, white = 0;
        double dist = 0.0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const size_t p = size_t(y) * kWidth + size_t(x);
                // Image and depth rows run top down.
                const glm::vec4 ndc((float(x) + 0.5f) / kWidth * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / kHeight * 2.0f,
                                    depth[p] * 2.0f - 1.0f, 1.0f);
                const glm::vec4 w = cam.inv_view_proj * ndc;
                const glm::vec3 pos = glm::vec3(w) / w.w;
                const float d = glm::distance(glm::vec2(pos.x, pos.z), centre_);
                if (d > radius || std::abs(pos.y - sea_level) > 0.25f) continue;
                ++sea;
                const uint8_t* px = &img.pixels[p * 4];
                const int lo = std::min({px[0], px[1], px[2]}), hi = std::max({px[0], px[1], px[2]});
                const float lum = (0.2126f * px[0] + 0.7152f * px[1] + 0.0722f * px[2]) / 255.0f;
                if (lum > 0.55f && float(lo) > 0.8f * float(hi)) {
                    ++white;
                    dist += d;
                }
            }
        c.white = sea ? double(white) / double(sea) : 0.0;
        c.radius_m = white ? dist / double(white) : 0.0;
        return c;
    }

    std::unique_ptr<RenderStage> stage_;
    glm::vec2 centre_{0.0f};
};

TEST_F(SplashFoamRender, FoamRisesWhereTheSplashFallsBackAndFades) {
    stage_ = std::make_unique<RenderStage>(
        game::GameSession{game::LoadedLevel{}, std::make_unique<sim::World>(make_test_level(),
                                                                            sim::standard_subsystems_with_water({}, 99))},
        StageOptions{.width = kWidth, .height = kHeight, .passes = kWaterFrame});
    sim::World& world = stage_->world();
    const sim::WaterSim& water = world.get<sim::WaterSim>();
    world.get<sim::ThrownObjects>().launch(sim::ThrownObjects::kHeavy, kDropPoint, {0.0f, -1.0f, 0.0f}, glm::vec3(0.0f));
    uint64_t splash = 0;
    for (int t = 0; t < 120 && !splash; ++t) {
        world.step(sim::TickInput{});
        for (const sim::SplashEvent& e : water.splashes())
            if (e.kind == sim::SplashEvent::Kind::First) splash = world.tick(), centre_ = {e.position.x, e.position.z};
    }
    ASSERT_GT(splash, 0u) << "the stone never splashed";
    sim::CameraView above;
    above.eye = {centre_.x + 1.0f, water.sea_level() + 6.0f, centre_.y - 3.5f};
    above.target = {centre_.x, water.sea_level(), centre_.y};
    above.fov_y_deg = 50.0f;
    const effects::Camera cam = stage_->camera(above);

    // Seconds after the first splash at which the foam is measured.
    const std::vector<double> at_s = {0.15, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0};
    std::map<double, Coverage> measured;
    for (size_t next = 0; next < at_s.size();) {
        world.step(sim::TickInput{});
        const int64_t since = int64_t(world.tick()) - int64_t(splash);
        const bool measure = since >= std::lround(at_s[next] * sim::kTickRateHz);
        if (!measure && since % 6 != 0) continue;  // the foam follows the sheets every few ticks
        const auto img = stage_->render(cam, {.time_s = double(world.tick()) * sim::kTickSeconds});
        if (!measure) continue;
        const Coverage c = coverage(img, stage_->depth(), cam, water.sea_level(), 2.5f);
        measured[at_s[next]] = c;
        std::printf("foam %.2f s after the splash: %.1f%% of the sea within 2.5 m white, %.2f m out on average\n",
                    at_s[next], 100.0 * c.white, c.radius_m);
        maybe_write_png("foam_" + std::to_string(int(at_s[next] * 100)) + "cs", img);
        ++next;
    }
    double peak = 0.0, peak_s = 0.0;
    for (const auto& [s, c] : measured)
        if (c.white > peak) peak = c.white, peak_s = s;
    EXPECT_LT(measured[0.15].white, 0.02) << "little white water before the splash falls back";
    EXPECT_GE(peak, 0.1) << "white water where the splash fell back";
    EXPECT_GE(peak_s, 1.0) << "the foam is left by the falling water, after the crown";
    EXPECT_LE(measured[5.0].white, 0.3 * peak) << "the foam fades within a few seconds";
    EXPECT_GT(measured[3.0].radius_m, measured[1.0].radius_m) << "the foam spreads";
}
