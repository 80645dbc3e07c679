// A stone dropped into calm water, close up from the side: the first splash's crown
// must rise as one sheet (its pixels one connected region, not a scatter of shards),
// and its height and rim radius must follow the stone's size and speed. Set
// SPINDRIFT_WATER_PNG_DIR to write the frames as PNGs.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "SimTestLevel.h"
#include "effects/water/WaterPass.h"
#include "effects/water/WaterView.h"
#include "game/capture/ImageFiles.h"
#include "sim/objects/ThrownObjects.h"
#include "sim/water/WaterSim.h"
#include "sim/world/World.h"

namespace {

constexpr int kWidth = 320, kHeight = 240;
const StagePasses kWaterFrame = kLitScene | kSceneCopyPass | kWaterPass | kTonemapPass;
const glm::vec3 kDropPoint{10.0f, 1.2f, 12.0f};  // over open water, 12 m off the test level's shore

// The test level with a wave grid as the sea.
std::unique_ptr<sim::World> world_with_water() {
    return std::make_unique<sim::World>(make_test_level(), sim::standard_subsystems_with_water({}, 99));
}

// Drops a stone straight down at `speed`; steps until it splashes and returns the
// index of the sheet it raised (-1 if it never did).
int drop_stone(sim::World& world, sim::WaterSim& water, const sim::ThrowKind& stone) {
    world.get<sim::ThrownObjects>().launch(stone, kDropPoint, {0.0f, -1.0f, 0.0f}, glm::vec3(0.0f));
    for (int t = 0; t < 120; ++t) {
        world.step(sim::TickInput{});
        for (const sim::SplashEvent& e : water.splashes())
            if (e.kind == sim::SplashEvent::Kind::First) return e.sheet;
    }
    return -1;
}

struct Crown {
    float height_m = 0.0f;  // highest the sheet rose above sea level
    float rim_radius_m = 0.0f;  // mean distance from the impact of its top edge, at that moment
};

// The crown a stone of this size dropped at this speed throws, measured in the sim.
Crown measure_crown(float radius_m, float speed_mps) {
    const std::unique_ptr<sim::World> owned = world_with_water();
    sim::World& world = *owned;
    sim::WaterSim& water = world.get<sim::WaterSim>();
    const int k = drop_stone(world, water, {radius_m, 2600.0f, speed_mps});
    EXPECT_GE(k, 0) << "the stone never splashed";
    if (k < 0) return {};
    const sim::SplashSheet& sheet = water.sheets()[size_t(k)];
    const glm::vec2 centre = sheet.centre_xz();
    Crown best;
    for (int t = 0; t < 120 && sheet.active(); ++t) {
        world.step(sim::TickInput{});
        const auto& s = water.splashes();
        if (std::any_of(s.begin(), s.end(), [](const sim::SplashEvent& e) { return e.kind == sim::SplashEvent::Kind::Second; }))
            break;  // the jet: the crown is what rose before it
        float top = -1e9f;
        for (size_t i = 0; i < sheet.positions().size(); ++i)
            if (sheet.airborne()[i]) top = std::max(top, sheet.positions()[i].y - water.sea_level());
        if (top > best.height_m) {
            // The top edge: the airborne vertices within 10% of the highest.
            double sum = 0.0;
            int n = 0;
            for (size_t i = 0; i < sheet.positions().size(); ++i) {
                const glm::vec3 p = sheet.positions()[i];
                if (!sheet.airborne()[i] || p.y - water.sea_level() < 0.9f * top) continue;
                sum += std::hypot(p.x - centre.x, p.z - centre.y);
                ++n;
            }
            best = {top, float(sum / std::max(n, 1))};
        }
    }
    return best;
}

// The largest 8-connected region of the mask and the mask's size.
struct Regions {
    int largest = 0, total = 0, count = 0;
};
Regions regions(const std::vector<uint8_t>& mask, int w, int h) {
    Regions r;
    std::vector<int> label(mask.size(), 0), stack;
    for (size_t start = 0; start < mask.size(); ++start) {
        if (!mask[start] || label[start]) continue;
        ++r.count;
        int size = 0;
        stack.assign(1, int(start));
        label[start] = r.count;
        while (!stack.empty()) {
            const int p = stack.back();
            stack.pop_back();
            ++size;
            const int x = p % w, y = p / w;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const size_t q = size_t(ny) * size_t(w) + size_t(nx);
                    if (mask[q] && !label[q]) {
                        label[q] = r.count;
                        stack.push_back(int(q));
                    }
                }
        }
        r.total += size;
        r.largest = std::max(r.largest, size);
    }
    return r;
}

void maybe_write_png(const std::string& name, const game::ImageRGBA8& img) {
    if (const char* dir = std::getenv("SPINDRIFT_WATER_PNG_DIR"))
        game::write_png(std::filesystem::path(dir) / (name + ".png"), img);
}

}  // namespace

TEST(SplashCrown, HeightAndRimRadiusFollowTheStonesSizeAndSpeed) {
    const Crown base = measure_crown(0.2f, 8.0f);
    const Crown faster = measure_crown(0.2f, 13.0f);
    const Crown bigger = measure_crown(0.28f, 8.0f);
    EXPECT_GT(base.height_m, 0.1f) << "a 20 cm stone thrown down at 8 m/s should throw a crown";
    EXPECT_GT(faster.height_m, 1.3f * base.height_m) << "a faster stone throws a taller crown";
    EXPECT_GT(bigger.height_m, 1.3f * base.height_m) << "a bigger stone throws a taller crown";
    EXPECT_GT(bigger.rim_radius_m, base.rim_radius_m) << "a bigger stone opens a wider crown";
    EXPECT_GT(faster.rim_radius_m, base.rim_radius_m) << "a faster stone's crown flies out further";
    // The crown stands round the hole the stone made, not over it.
    EXPECT_GT(base.rim_radius_m, 0.2f);
}

class SplashCrownRender : public HeadlessTest {
protected:
    void SetUp() override {
        HeadlessTest::SetUp();
        stage_ = std::make_unique<RenderStage>(game::GameSession{game::LoadedLevel{}, world_with_water()},
                                               StageOptions{.width = kWidth, .height = kHeight, .passes = kWaterFrame});
        stage_->pass<effects::WaterPass>().look().ripples = 0.0f;
    }
    void TearDown() override { stage_.reset(); }

    // Renders the world's water as the view says (the stone and the grid as they are).
    game::ImageRGBA8 render(const effects::Camera& camera, const effects::WaterView& view) {
        auto draw_view = [&](const effects::FrameContext& f) { stage_->pass<effects::WaterPass>().draw(f, view); };
        return stage_->render(camera, {.replaced = kWaterPass, .replacement = draw_view});
    }

    std::unique_ptr<RenderStage> stage_;
};

TEST_F(SplashCrownRender, TheRisingCrownIsOneSheet) {
    sim::World& world = stage_->world();
    sim::WaterSim& water = world.get<sim::WaterSim>();
    const int k = drop_stone(world, water, sim::ThrownObjects::kHeavy);
    ASSERT_GE(k, 0) << "the stone never splashed";
    const glm::vec2 centre = water.sheets()[size_t(k)].centre_xz();
    sim::CameraView side;  // close up, from the side, a little above the water
    side.eye = {centre.x - 0.3f, 0.6f, centre.y - 2.6f};
    side.target = {centre.x, 0.45f, centre.y};
    side.fov_y_deg = 45.0f;
    const effects::Camera camera = stage_->camera(side);

    float last_top = 0.0f;
    int checked = 0;
    bool rising = true;
    for (int t = 1; t <= 60; ++t) {
        world.step(sim::TickInput{});
        if (t % 3 != 0) continue;
        const sim::SplashSheet& sheet = water.sheets()[size_t(k)];
        float top = 0.0f;
        for (size_t i = 0; i < sheet.positions().size(); ++i)
            if (sheet.airborne()[i]) top = std::max(top, sheet.positions()[i].y);
        rising = rising && top > last_top;  // the crown, until it tops out
        last_top = std::max(top, last_top);
        if (!rising && !std::getenv("SPINDRIFT_WATER_PNG_DIR")) break;  // the rest only to look at

        effects::WaterView view;
        effects::gather_water_view(world, view);
        if (std::getenv("SPINDRIFT_WATER_PNG_DIR")) maybe_write_png("crown_spray_t" + std::to_string(t), render(camera, view));
        view.spray.clear();  // the sheet alone
        const auto with_sheet = render(camera, view);
        const auto depth_with = stage_->depth();
        view.sheets.clear();
        const auto without = render(camera, view);
        const auto depth_without = stage_->depth();
        maybe_write_png("crown_t" + std::to_string(t), with_sheet);

        std::vector<uint8_t> mask(size_t(kWidth) * kHeight, 0);
        for (size_t p = 0; p < mask.size(); ++p) {
            int diff = 0;
            for (int c = 0; c < 3; ++c)
                diff = std::max(diff, std::abs(int(with_sheet.pixels[p * 4 + c]) - int(without.pixels[p * 4 + c])));
            mask[p] = diff > 6 || depth_with[p] != depth_without[p];
        }
        const Regions r = regions(mask, kWidth, kHeight);
        SCOPED_TRACE("tick " + std::to_string(t) + " after the splash: " + std::to_string(r.count) + " regions, " +
                     std::to_string(r.largest) + " of " + std::to_string(r.total) + " pixels in the largest");
        if (!rising) continue;  // only looked at
        ASSERT_GT(r.total, 200) << "the crown should cover a few hundred pixels close up";
        EXPECT_GE(r.largest, int(0.8 * r.total)) << "the crown should be one sheet, not shards";
        ++checked;
    }
    EXPECT_GE(checked, 2) << "the crown should rise for a few frames";
}
