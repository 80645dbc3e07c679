// The fluid pass on a real headless context: the tank on a small level, seen through
// (refracted, tinted), its work confined to the tank's rectangle, a stone's splash
// drawn as its own layer, a splash cloud drawn as a soft layer whose opacity grows with
// its density, bad smoothing settings refused, and a close-up through the
// harbour's tank after a stone that matches its golden in tests/data/fluid
// (SPINDRIFT_UPDATE_GOLDENS=1 rewrites it). Set SPINDRIFT_FLUID_PNG_DIR to write the
// frames as PNGs.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "SimTestLevel.h"
#include "effects/fluid/FluidPass.h"
#include "game/capture/FrameCompare.h"
#include "game/capture/ImageFiles.h"
#include "sim/fluid/FluidTank.h"
#include "sim/objects/ThrownObjects.h"

namespace {

constexpr int kWidth = 320, kHeight = 240;

sim::LevelDesc tank_level() {
    sim::LevelDesc l = make_test_level();
    l.tank_spot = {24.0f, 1.0f, 30.0f};
    l.fluid.enabled = true;
    l.fluid.particle_count = 4000;
    l.fluid.particle_radius_m = 0.03f;
    l.fluid.inner_size_m = {1.4f, 1.0f, 1.4f};
    return l;
}

sim::CameraView tank_view() {
    sim::CameraView v;
    v.eye = {24.5f, 2.6f, 26.5f};
    v.target = {24.0f, 1.35f, 30.0f};
    v.fov_y_deg = 45.0f;
    return v;
}

// The lit scene, the water, the tank and the tonemap.
const StagePasses kTankFrame = kLitScene | kSceneCopyPass | kWaterPass | kFluidPass | kTonemapPass;

void maybe_write_png(const std::string& name, const game::ImageRGBA8& img) {
    if (const char* dir = std::getenv("SPINDRIFT_FLUID_PNG_DIR"))
        game::write_png(std::filesystem::path(dir) / (name + ".png"), img);
}

glm::vec3 pixel(const game::ImageRGBA8& img, int x, int y) {
    const uint8_t* p = &img.pixels[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
    return {float(p[0]), float(p[1]), float(p[2])};
}

float difference(const game::ImageRGBA8& a, const game::ImageRGBA8& b, int x, int y) {
    return glm::length(pixel(a, x, y) - pixel(b, x, y));
}

// Pixels where two frames differ by more than `threshold` (of 0..255 per channel).
int pixels_differing(const game::ImageRGBA8& a, const game::ImageRGBA8& b, float threshold) {
    int n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) n += difference(a, b, x, y) > threshold ? 1 : 0;
    return n;
}

class FluidRenderTest : public HeadlessTest {
protected:
    void SetUp() override {
        HeadlessTest::SetUp();
        stage_ = std::make_unique<RenderStage>(
            tank_level(), StageOptions{.width = kWidth, .height = kHeight, .passes = kTankFrame});
        for (int t = 0; t < 45; ++t) stage_->world().step({});  // settled
    }
    void TearDown() override { stage_.reset(); }

    // The world's tank, or (with `view`) the given one.
    game::ImageRGBA8 render(bool with_fluid, const effects::FluidView* view = nullptr) {
        if (!with_fluid) return stage_->render(camera_, {.skip = kFluidPass});
        if (!view) return stage_->render(camera_);
        auto draw_view = [&](const effects::FrameContext& frame) { fluid_pass().draw(frame, *view); };
        return stage_->render(camera_, {.replaced = kFluidPass, .replacement = draw_view});
    }
    effects::FluidPass& fluid_pass() { return stage_->pass<effects::FluidPass>(); }

    std::unique_ptr<RenderStage> stage_;
    const effects::Camera camera_ = effects::make_camera(tank_view(), float(kWidth) / float(kHeight));
};

TEST_F(FluidRenderTest, TheTankRefractsAndTintsOnlyInsideItsRectangle) {
    const game::ImageRGBA8 without = render(false);
    const game::ImageRGBA8 with = render(true);
    maybe_write_png("tank_without", without);
    maybe_write_png("tank_with", with);
    const glm::ivec4 r = fluid_pass().last_rect();
    ASSERT_GT(r.z - r.x, 20);
    ASSERT_GT(r.w - r.y, 20);
    // The rectangle is a part of the screen, not all of it.
    EXPECT_LT(double(r.z - r.x) * double(r.w - r.y), 0.6 * kWidth * kHeight);
    int outside_changed = 0, inside_changed = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const int gl_y = kHeight - 1 - y;  // image rows are top-down
            const bool inside = x >= r.x && x < r.z && gl_y >= r.y && gl_y < r.w;
            const bool changed = glm::length(pixel(without, x, y) - pixel(with, x, y)) > 6.0f;
            (inside ? inside_changed : outside_changed) += changed ? 1 : 0;
        }
    EXPECT_EQ(outside_changed, 0);
    EXPECT_GT(inside_changed, 1500);

    // Beer-Lambert: with the liquid's absorption, red (absorbed most) falls against
    // green and blue where the liquid is, compared with a clear liquid.
    const float absorption = fluid_pass().look().absorption_per_m;
    fluid_pass().look().absorption_per_m = 0.0f;
    const game::ImageRGBA8 clear = render(true);
    fluid_pass().look().absorption_per_m = absorption;
    maybe_write_png("tank_clear", clear);
    glm::vec3 tinted_sum(0.0f), clear_sum(0.0f);
    int liquid = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            if (glm::length(pixel(clear, x, y) - pixel(with, x, y)) > 6.0f) {
                tinted_sum += pixel(with, x, y);
                clear_sum += pixel(clear, x, y);
                ++liquid;
            }
    ASSERT_GT(liquid, 500);
    const glm::vec3 tinted = tinted_sum / float(liquid), see_through = clear_sum / float(liquid);
    EXPECT_LT(tinted.x / (tinted.y + tinted.z), 0.9f * see_through.x / (see_through.y + see_through.z));
    EXPECT_GT(tinted.y + tinted.z, 60.0f);  // not black
}

TEST_F(FluidRenderTest, TheLiquidBendsTheBackgroundBeyondTheGlassTint) {
    // A clear liquid, so what changes is where each pixel looks, not its colour.
    fluid_pass().look().absorption_per_m = 0.0f;
    const game::ImageRGBA8 without = render(false);
    fluid_pass().look().ior = 1.0f;
    const game::ImageRGBA8 unbent = render(true);
    fluid_pass().look().ior = 1.33f;
    const game::ImageRGBA8 bent = render(true);
    maybe_write_png("tank_ior_1_00", unbent);
    maybe_write_png("tank_ior_1_33", bent);
    // With the index of air the rays go straight through: the scene behind, under the
    // glass's tint and faint mirror (and Schlick's grazing reflection at the rim). Both
    // frames have the same glass, so what water's index changes beyond the most the
    // glass changes (its 95th percentile) is background moved to other pixels.
    std::vector<float> glass;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            if (float d = difference(without, unbent, x, y); d > 1.0f) glass.push_back(d);
    ASSERT_GT(glass.size(), 2000u);
    std::nth_element(glass.begin(), glass.begin() + std::ptrdiff_t(glass.size() * 95 / 100), glass.end());
    const float tint = std::max(glass[glass.size() * 95 / 100], 12.0f);
    const int displaced = pixels_differing(unbent, bent, tint);
    EXPECT_GT(displaced, 1000) << "beyond the glass's " << tint;  // 2719 here
}

TEST_F(FluidRenderTest, AStoneSplashesDropsThatAreDrawnAsTheirOwnLayer) {
    sim::World& world = stage_->world();
    world.get<sim::ThrownObjects>().launch({0.2f, 2600.0f, 0.0f}, {24.0f, 3.2f, 30.0f}, {0, 0, 1}, {0, 0, 0});
    // Until the drops are up (at most a second).
    for (int t = 0; t < 60 && world.get<sim::FluidTank>().fluid().splash_count() < 25; ++t) world.step({});
    effects::FluidView view;
    ASSERT_TRUE(effects::gather_fluid_view(world, view));
    ASSERT_GE(view.splash.size(), 25u);
    const game::ImageRGBA8 splash = render(true);
    maybe_write_png("tank_splash", splash);
    // Without the splash layer, those pixels show what is behind the drops.
    const glm::ivec4 r = fluid_pass().last_rect();
    int drop_pixels = 0;
    for (const sim::FluidEllipsoid& e : view.splash) {
        glm::vec4 c = camera_.view_proj * glm::vec4(e.centre, 1.0f);
        glm::vec2 px = (glm::vec2(c) / c.w * 0.5f + 0.5f) * glm::vec2(kWidth, kHeight);
        drop_pixels += (px.x >= r.x && px.x < r.z && px.y >= r.y && px.y < r.w) ? 1 : 0;
    }
    EXPECT_GT(drop_pixels, 10);  // the rectangle grew to hold the flying drops
    // Without the splash layer, the pixels where drops fly change (to the body or the
    // scene behind them).
    effects::FluidView body_only = view;
    body_only.splash.clear();
    const game::ImageRGBA8 no_drops = render(true, &body_only);
    maybe_write_png("tank_splash_emptied", no_drops);
    EXPECT_GT(pixels_differing(splash, no_drops, 12.0f), 100);  // 175 here
    int drops_seen = 0, drops_on_screen = 0;
    for (const sim::FluidEllipsoid& e : view.splash) {
        glm::vec4 c = camera_.view_proj * glm::vec4(e.centre, 1.0f);
        glm::ivec2 px(glm::floor((glm::vec2(c) / c.w * 0.5f + 0.5f) * glm::vec2(kWidth, kHeight)));
        if (px.x < 1 || px.y < 1 || px.x >= kWidth - 1 || px.y >= kHeight - 1) continue;
        ++drops_on_screen;
        bool changed = false;  // in the drop's pixel or a neighbour (image rows are top-down)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                changed = changed || difference(splash, no_drops, px.x + dx, kHeight - 1 - px.y + dy) > 12.0f;
        drops_seen += changed ? 1 : 0;
    }
    ASSERT_GT(drops_on_screen, 10);
    // Most drops show; some are hidden behind the body or each other.
    EXPECT_GT(drops_seen, drops_on_screen / 2) << drops_seen << " of " << drops_on_screen;  // 22 of 25 here
}

// A ball of `count` splash drops of radius r, on a fixed lattice (the same ball, denser).
std::vector<sim::FluidEllipsoid> splash_ball(glm::vec3 centre, float ball_m, int count, float r) {
    std::vector<sim::FluidEllipsoid> out;
    for (int k = 0; k < count; ++k) {
        // Golden-angle spiral over the sphere, at radii filling the ball evenly.
        const float f = (float(k) + 0.5f) / float(count);
        const float y = 1.0f - 2.0f * f, ring = std::sqrt(std::max(0.0f, 1.0f - y * y));
        const float phi = 2.39996323f * float(k), depth = std::cbrt(float((k * 7) % count + 1) / float(count));
        sim::FluidEllipsoid e;
        e.centre = centre + ball_m * depth * glm::vec3(ring * std::cos(phi), y, ring * std::sin(phi));
        e.axis[0] = {r, 0, 0};
        e.axis[1] = {0, r, 0};
        e.axis[2] = {0, 0, r};
        out.push_back(e);
    }
    return out;
}

// The splash is a soft layer, not a scatter of dots: a sparse cloud of drops shows as
// faint, intermediate pixels (none near white), and the same cloud denser is more
// opaque over the same area, its thickness target holding more water.
TEST_F(FluidRenderTest, ASplashCloudIsASoftLayerWhoseOpacityGrowsWithItsDensity) {
    effects::FluidView base;
    ASSERT_TRUE(effects::gather_fluid_view(stage_->world(), base));
    base.splash.clear();
    const game::ImageRGBA8 bare = render(true, &base);
    const glm::vec3 centre(24.1f, 1.85f, 29.2f);  // above the liquid, in front of the glass
    auto render_cloud = [&](int count, double& thickness) {
        effects::FluidView v = base;
        v.splash = splash_ball(centre, 0.18f, count, 0.03f);
        game::ImageRGBA8 img = render(true, &v);
        const effects::gl::Texture& t = fluid_pass().splash_thickness();
        std::vector<float> texels(size_t(t.width()) * size_t(t.height()));
        glGetTextureImage(t.id(), 0, GL_RED, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
        thickness = 0.0;
        for (float x : texels) thickness += double(x);
        return img;
    };
    double sparse_t = 0.0, dense_t = 0.0;
    const game::ImageRGBA8 sparse = render_cloud(24, sparse_t);
    const game::ImageRGBA8 dense = render_cloud(240, dense_t);
    maybe_write_png("splash_cloud_sparse", sparse);
    maybe_write_png("splash_cloud_dense", dense);
    EXPECT_GT(dense_t, 5.0 * sparse_t) << sparse_t << " against " << dense_t;

    // Brightening over the cloud's square on screen (image rows are top-down).
    const glm::vec4 c = camera_.view_proj * glm::vec4(centre, 1.0f);
    const glm::ivec2 mid(glm::floor((glm::vec2(c) / c.w * 0.5f + 0.5f) * glm::vec2(kWidth, kHeight)));
    const int half = 10;
    double sparse_sum = 0.0, dense_sum = 0.0;
    float sparse_max = 0.0f;
    int dense_covered = 0;
    for (int y = mid.y - half; y <= mid.y + half; ++y)
        for (int x = mid.x - half; x <= mid.x + half; ++x) {
            const int row = kHeight - 1 - y;
            const float lift_sparse = glm::dot(pixel(sparse, x, row) - pixel(bare, x, row), glm::vec3(1.0f / 3.0f));
            const float lift_dense = glm::dot(pixel(dense, x, row) - pixel(bare, x, row), glm::vec3(1.0f / 3.0f));
            sparse_sum += lift_sparse;
            dense_sum += lift_dense;
            sparse_max = std::max(sparse_max, lift_sparse);
            dense_covered += lift_dense > 8.0f ? 1 : 0;
        }
    const glm::vec3 white(255.0f);
    const float room = glm::dot(white - pixel(bare, mid.x, kHeight - 1 - mid.y), glm::vec3(1.0f / 3.0f));
    EXPECT_GT(sparse_sum, 0.0) << "the sparse cloud shows";
    EXPECT_LT(sparse_max, 0.5f * room) << "no drop of the sparse cloud is a saturated dot";
    // Ten times the water, well more light (opacity saturates as 1 - exp: 1.75x here).
    EXPECT_GT(dense_sum, 1.4 * sparse_sum) << sparse_sum << " against " << dense_sum;
    // The dense cloud covers its square as one layer, not a scatter of points.
    EXPECT_GT(dense_covered, (2 * half + 1) * (2 * half + 1) / 2) << dense_covered;
}

TEST_F(FluidRenderTest, RefusesBadSmoothingSettings) {
    fluid_pass().set_smoothing(effects::FluidSmoothing::defaults(effects::SmoothingMethod::Bilateral));
    effects::FluidSmoothing s;
    s.kernel_size = 8;
    EXPECT_THROW(fluid_pass().set_smoothing(s), std::invalid_argument);
    s.kernel_size = 17;
    EXPECT_THROW(fluid_pass().set_smoothing(s), std::invalid_argument);
    s.kernel_size = 9;
    s.iterations = 0;
    EXPECT_THROW(fluid_pass().set_smoothing(s), std::invalid_argument);
    EXPECT_THROW(effects::smoothing_method("gaussian"), std::invalid_argument);
    // A refused setting leaves the pass as it was.
    EXPECT_EQ(fluid_pass().smoothing().method, effects::SmoothingMethod::Bilateral);
    EXPECT_EQ(fluid_pass().smoothing().kernel_size, 7);
    EXPECT_EQ(fluid_pass().smoothing().iterations, 22);
    // Each of the three methods draws the liquid, and each smooths it its own way.
    const game::ImageRGBA8 without = render(false);
    std::vector<game::ImageRGBA8> images;
    for (auto m : {effects::SmoothingMethod::PlaneFit, effects::SmoothingMethod::Bilateral,
                   effects::SmoothingMethod::NarrowRange}) {
        EXPECT_EQ(effects::smoothing_method(effects::smoothing_name(m)), m);
        fluid_pass().set_smoothing(effects::FluidSmoothing::defaults(m));
        images.push_back(render(true));
        maybe_write_png("tank_" + std::string(effects::smoothing_name(m)), images.back());
        // About 10500 pixels here, the glass included.
        EXPECT_GT(pixels_differing(without, images.back(), 6.0f), 5000) << effects::smoothing_name(m);
    }
    for (size_t a = 0; a < images.size(); ++a)
        for (size_t b = a + 1; b < images.size(); ++b)
            EXPECT_GT(pixels_differing(images[a], images[b], 6.0f), 1000) << "methods " << a << " and " << b;  // 5200-5400
}

// The README's close-up: the harbour's tank at the pier's end just after a stone fell
// in, seen from the pier at the liquid's height, so the sea and the horizon behind
// it, and the stone inside, are bent through the front and back surfaces and tinted.
class FluidCloseUpTest : public FluidRenderTest {
protected:
    void SetUp() override { HeadlessTest::SetUp(); }  // no settled tank: each test makes its own
};

// 2.6 m from the tank's centre, off to the side of the pier's axis, at the liquid's
// middle height, so the horizon runs through the liquid.
sim::CameraView through_the_tank() {
    sim::CameraView v;
    v.eye = {23.0f, 1.72f, 33.9f};
    v.target = {21.9f, 1.66f, 36.3f};
    v.fov_y_deg = 38.0f;
    return v;
}

TEST_F(FluidCloseUpTest, ThroughTheTankAtTheHarbourMatchesItsGolden) {
    RenderStage stage("harbour", {.width = 640, .height = 360, .passes = kTankFrame});
    sim::World& world = stage.world();
    // A stone dropped into the tank; 40 ticks on, it has bounced off the floor and the
    // liquid it threw up stands around it.
    const glm::vec3 spot = world.level().tank_spot;
    world.get<sim::ThrownObjects>().launch({0.2f, 2600.0f, 0.0f}, spot + glm::vec3(0.1f, 1.7f, 0.2f), {0, 0, 1},
                                           {0, 0, 0});
    for (int t = 0; t < 40; ++t) world.step({});
    EXPECT_GE(world.get<sim::FluidTank>().fluid().splash_count(), 5u);  // 15 here
    const game::ImageRGBA8 bare = stage.render(through_the_tank(), {.skip = kFluidPass});
    const game::ImageRGBA8 through = stage.render(through_the_tank());
    maybe_write_png("closeup_bare", bare);
    maybe_write_png("closeup_through", through);

    // Where the body's smoothed front depth map has liquid, the harbour behind is
    // bent and tinted: those pixels change, and red, absorbed most, falls against
    // green and blue. The liquid is a sizeable share of the frame.
    const int w = through.width, h = through.height;
    std::vector<float> front(size_t(w) * size_t(h));
    glGetTextureImage(stage.pass<effects::FluidPass>().body_front().id(), 0, GL_RED, GL_FLOAT,
                      GLsizei(front.size() * sizeof(float)), front.data());
    glm::vec3 tinted_sum(0.0f), bare_sum(0.0f);
    int liquid = 0, changed = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float d = front[size_t(h - 1 - y) * size_t(w) + size_t(x)];  // GL rows are bottom-up
            if (!(d > 0.0f && d < 1.0e5f)) continue;
            ++liquid;
            changed += difference(bare, through, x, y) > 12.0f ? 1 : 0;
            tinted_sum += pixel(through, x, y);
            bare_sum += pixel(bare, x, y);
        }
    const double share = double(liquid) / double(w * h);
    EXPECT_GT(share, 0.12);  // 0.16 here
    ASSERT_GT(liquid, 0);
    EXPECT_GT(double(changed) / liquid, 0.9);  // 0.96 here
    const glm::vec3 tinted = tinted_sum / float(liquid), behind = bare_sum / float(liquid);
    EXPECT_LT(tinted.x / (tinted.y + tinted.z), 0.8f * behind.x / (behind.y + behind.z));  // 0.29 against 0.45 here
    EXPECT_GT(tinted.y + tinted.z, 150.0f);  // see-through, not dark: 337 here

    const std::filesystem::path golden = std::filesystem::path(SPINDRIFT_TEST_DATA) / "fluid" / "through_the_tank.png";
    if (const char* update = std::getenv("SPINDRIFT_UPDATE_GOLDENS"); update && std::string(update) == "1") {
        std::filesystem::create_directories(golden.parent_path());
        game::write_png(golden, through);
    }
    const game::CompareResult r = game::compare_frames(through, game::read_png(golden));
    EXPECT_TRUE(r.passed) << golden << ": " << r.summary;
}

}  // namespace
