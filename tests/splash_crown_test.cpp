// A stone dropped into calm water, close up from the side: the first splash's crown
// must rise as one sheet (its pixels one connected region, not a scatter of shards),
// and its height and rim radius must follow the stone's size and speed. It must read
// as water: clear, so a pattern moved behind it shows through, white only at its rim,
// and its second splash a narrow jet. Set SPINDRIFT_WATER_PNG_DIR to write the frames
// as PNGs.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "SimTestLevel.h"
#include "effects/gl/PipelineState.h"
#include "effects/water/WaterPass.h"
#include "effects/water/WaterView.h"
#include "game/capture/ImageFiles.h"
#include "game/replay/CameraTrack.h"
#include "game/replay/ReplayReader.h"
#include "sim/player/CameraRig.h"
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
    glm::ivec4 largest_box{0};  // the largest region's x0, y0, x1, y1 (inclusive)
};
Regions regions(const std::vector<uint8_t>& mask, int w, int h) {
    Regions r;
    std::vector<int> label(mask.size(), 0), stack;
    for (size_t start = 0; start < mask.size(); ++start) {
        if (!mask[start] || label[start]) continue;
        ++r.count;
        int size = 0;
        glm::ivec4 box(int(start) % w, int(start) / w, int(start) % w, int(start) / w);
        stack.assign(1, int(start));
        label[start] = r.count;
        while (!stack.empty()) {
            const int p = stack.back();
            stack.pop_back();
            ++size;
            const int x = p % w, y = p / w;
            box = glm::ivec4(std::min(box.x, x), std::min(box.y, y), std::max(box.z, x), std::max(box.w, y));
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
        if (size > r.largest) r.largest_box = box;
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

// Where the sheet stands in front of what is behind it: the window depth differs.
std::vector<uint8_t> depth_mask(const std::vector<float>& with, const std::vector<float>& without) {
    std::vector<uint8_t> mask(with.size(), 0);
    for (size_t p = 0; p < mask.size(); ++p) mask[p] = with[p] != without[p];
    return mask;
}

// The crown's rim: the top `band` pixels of the mask in each column (seen from the
// side, its top edge is the torn rim); its interior: the pixels at least `inset` from
// anything outside the mask, and not rim.
struct CrownParts {
    std::vector<size_t> rim, interior;
};
CrownParts crown_parts(const std::vector<uint8_t>& mask, int w, int h, int band = 3, int inset = 4) {
    CrownParts parts;
    std::vector<uint8_t> rim(mask.size(), 0);
    for (int x = 0; x < w; ++x) {
        int y = 0;
        while (y < h && !mask[size_t(y) * size_t(w) + size_t(x)]) ++y;
        for (int k = 0; k < band && y + k < h && mask[size_t(y + k) * size_t(w) + size_t(x)]; ++k) {
            rim[size_t(y + k) * size_t(w) + size_t(x)] = 1;
            parts.rim.push_back(size_t(y + k) * size_t(w) + size_t(x));
        }
    }
    for (int y = inset; y < h - inset; ++y)
        for (int x = inset; x < w - inset; ++x) {
            const size_t p = size_t(y) * size_t(w) + size_t(x);
            bool inside = mask[p] && !rim[p];
            for (int dy = -inset; inside && dy <= inset; ++dy)
                for (int dx = -inset; inside && dx <= inset; ++dx)
                    inside = mask[size_t(y + dy) * size_t(w) + size_t(x + dx)] != 0;
            if (inside) parts.interior.push_back(p);
        }
    return parts;
}

float luminance01(const game::ImageRGBA8& img, size_t p) {
    const uint8_t* c = &img.pixels[p * 4];
    return (0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2]) / 255.0f;
}
bool white(const game::ImageRGBA8& img, size_t p) {
    const uint8_t* c = &img.pixels[p * 4];
    const int lo = std::min({c[0], c[1], c[2]}), hi = std::max({c[0], c[1], c[2]});
    return hi > 0 && float(lo) / float(hi) > 0.9f && luminance01(img, p) > 0.8f;
}
float median_luminance(const game::ImageRGBA8& img, const std::vector<size_t>& pixels) {
    std::vector<float> l;
    for (size_t p : pixels) l.push_back(luminance01(img, p));
    if (l.empty()) return 0.0f;
    std::nth_element(l.begin(), l.begin() + std::ptrdiff_t(l.size() / 2), l.end());
    return l[l.size() / 2];
}

// Window depth of a world point.
float window_depth(const effects::Camera& camera, glm::vec3 p) {
    const glm::vec4 clip = camera.view_proj * glm::vec4(p, 1.0f);
    return 0.5f * clip.z / clip.w + 0.5f;
}

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

// harbour_boat's crown (682) and jet (703) as the replay renders them: the stone thrown
// from the boat, seen from the side by the script's cameras 3 m off.
class SplashCheckpoint : public HeadlessTest {
protected:
    void replay_to(uint32_t tick) {
        const game::Replay replay = game::read_replay(
            std::filesystem::path(SPINDRIFT_TEST_DATA).parent_path().parent_path() / "replays" / "harbour_boat.replay");
        const game::ReplayHeader& h = replay.header;
        ASSERT_NE(std::find(h.checkpoints.begin(), h.checkpoints.end(), tick), h.checkpoints.end());
        stage_ = std::make_unique<RenderStage>(game::GameSession::open(h.level_id, 1, h.seed),
                                               StageOptions{.width = int(h.frame_width), .height = int(h.frame_height)});
        sim::World& world = stage_->world();
        for (uint32_t t = 0; t < tick && t < replay.inputs.size(); ++t) world.step(replay.inputs[t]);
        view_ = game::CameraTrack(h.camera_shots, h.tick_rate_hz).view_at(tick, world.get<sim::CameraRig>().view());
        time_s_ = double(tick) * sim::kTickSeconds;
        effects::gather_water_view(world, water_);
        water_.spray.clear();  // the sheets alone
        // The splash the camera looks at: the sheet nearest its target.
        float nearest = 1e9f;
        for (const sim::SplashSheet& s : world.get<sim::WaterSim>().sheets()) {
            const float d = glm::distance(s.centre_xz(), glm::vec2(view_.target.x, view_.target.z));
            if (s.active() && d < nearest) nearest = d, centre_ = s.centre_xz();
        }
        ASSERT_LT(nearest, 2.0f) << "no splash in front of the checkpoint's camera";
    }

    // The checkpoint's frame with the given water, and the window depth it left.
    game::ImageRGBA8 render(const effects::WaterView& water, std::vector<float>* depth = nullptr) {
        RenderStage& stage = *stage_;
        auto draw = [&](const effects::FrameContext& f) { stage.pass<effects::WaterPass>().draw(f, water); };
        auto img = stage.render(view_, {.time_s = time_s_, .replaced = kWaterPass, .replacement = draw});
        if (depth) *depth = stage.depth();
        return img;
    }
    // Where the sheets stand in front of what is behind them.
    std::vector<uint8_t> sheet_mask() {
        std::vector<float> with, without;
        render(water_, &with);
        effects::WaterView bare = water_;
        bare.sheets.clear();
        render(bare, &without);
        return depth_mask(with, without);
    }

    // The checkpoint's frame with the opaque scene replaced by a wall of checks
    // standing square to the view at `wall_depth` (window depth), its checks shifted by
    // `shift` squares.
    game::ImageRGBA8 render_before_wall(float wall_depth, int shift) {
        RenderStage& stage = *stage_;
        bool copied = false;
        const effects::WaterView& view = water_;
        auto draw = [&](const effects::FrameContext& f) {
            if (copied) {  // the water's turn
                stage.pass<effects::WaterPass>().draw(f, view);
                return;
            }
            effects::gl::apply(effects::gl::kInitialState);
            glBindFramebuffer(GL_FRAMEBUFFER, f.targets.hdr().id());
            glViewport(0, 0, f.targets.width(), f.targets.height());
            glClearBufferfv(GL_DEPTH, 0, &wall_depth);
            glEnable(GL_SCISSOR_TEST);
            constexpr int kCheck = 6;
            // A textured board in daylight: checks of twice the other's albedo (checks of five
            // times showed through today's pale sheet too).
            const float light[4] = {0.32f, 0.28f, 0.22f, 1.0f}, dark[4] = {0.16f, 0.14f, 0.11f, 1.0f};
            for (int y = 0; y < f.targets.height(); y += kCheck)
                for (int x = 0; x < f.targets.width(); x += kCheck) {
                    glScissor(x, y, kCheck, kCheck);
                    glClearBufferfv(GL_COLOR, 0, ((x / kCheck + y / kCheck + shift) % 2) ? light : dark);
                }
            glDisable(GL_SCISSOR_TEST);
            f.targets.copy_scene();
            copied = true;
        };
        return stage.render(view_, {.time_s = time_s_, .replaced = kSceneCopyPass | kWaterPass, .replacement = draw});
    }

    void TearDown() override { stage_.reset(); }

    std::unique_ptr<RenderStage> stage_;
    sim::CameraView view_;
    double time_s_ = 0.0;
    effects::WaterView water_;
    glm::vec2 centre_{0.0f};
};

// A real crown is clear water: what is behind it shows through, bent and darkened. A
// wall of checks 1.5 m behind the crown at 682 is shifted by one check: most of the
// crown's interior must change with it.
TEST_F(SplashCheckpoint, WhatIsBehindTheCrownShowsThrough) {
    replay_to(682);
    const auto mask = sheet_mask();
    const effects::Camera camera = stage_->camera(view_);
    const glm::vec3 forward = glm::normalize(glm::vec3(centre_.x, 0.5f, centre_.y) - view_.eye);
    const float wall = window_depth(camera, glm::vec3(centre_.x, 0.5f, centre_.y) + 1.5f * forward);
    const auto a = render_before_wall(wall, 0);
    const auto b = render_before_wall(wall, 1);
    maybe_write_png("crown_wall_a", a);
    maybe_write_png("crown_wall_b", b);
    const CrownParts parts = crown_parts(mask, stage_->width(), stage_->height());
    ASSERT_GT(parts.interior.size(), 1000u) << "the crown's interior should cover a thousand pixels close up";
    size_t changed = 0;
    for (size_t p : parts.interior) {
        int diff = 0;
        for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(int(a.pixels[p * 4 + c]) - int(b.pixels[p * 4 + c])));
        changed += diff > 10;
    }
    const double share = double(changed) / double(parts.interior.size());
    std::printf("crown see-through: %zu of %zu interior pixels change (%.1f%%)\n", changed, parts.interior.size(),
                100.0 * share);
    EXPECT_GE(share, 0.6) << "the crown should let what is behind it through, not hide it";
}

// Clear body, white rim: the crown's torn top edge is whiter than its body, and little of
// the body is white.
TEST_F(SplashCheckpoint, TheCrownIsClearWithAWhiteRim) {
    replay_to(682);
    const auto mask = sheet_mask();
    const auto img = render(water_);
    maybe_write_png("crown_look", img);
    const CrownParts parts = crown_parts(mask, stage_->width(), stage_->height());
    ASSERT_GT(parts.interior.size(), 1000u);
    ASSERT_GT(parts.rim.size(), 100u);
    const float rim = median_luminance(img, parts.rim), interior = median_luminance(img, parts.interior);
    size_t whites = 0;
    for (size_t p : parts.interior) whites += white(img, p);
    const double white_share = double(whites) / double(parts.interior.size());
    std::printf("crown look: rim median luminance %.3f, interior %.3f; white %.1f%% of the interior\n", rim, interior,
                100.0 * white_share);
    EXPECT_GE(rim - interior, 0.15f) << "the torn rim should read white over a clear body";
    EXPECT_LE(white_share, 0.25) << "the body of the crown should be clear, not white";
}

// The second splash is a jet: a column of water, at least 2.5 times as tall on screen as
// it is wide at its checkpoint (703).
TEST_F(SplashCheckpoint, TheSecondSplashIsANarrowJet) {
    replay_to(703);
    maybe_write_png("jet", render(water_));
    const Regions r = regions(sheet_mask(), stage_->width(), stage_->height());
    ASSERT_GT(r.largest, 200) << "the jet should cover a few hundred pixels";
    const int w = r.largest_box.z - r.largest_box.x + 1, h = r.largest_box.w - r.largest_box.y + 1;
    std::printf("jet: %d x %d pixels (%.2f times as tall as wide)\n", w, h, double(h) / w);
    EXPECT_GE(double(h), 2.5 * w) << "the jet should be a column, not a hood";
}

// A real crown's rim is beaded: the film's rolled-up edge gathers into drops. Along the
// crown's top edge at 682 there must be small bright blobs (a pixel the brightest of its
// 5x5 neighbourhood and at least 0.04 brighter than the mean of the 9x9 square round
// it), many more than on the same rim drawn without its drops.
TEST_F(SplashCheckpoint, TheRimIsBeadedWithDrops) {
    replay_to(682);
    const int w = stage_->width(), h = stage_->height();
    const CrownParts parts = crown_parts(sheet_mask(), w, h);
    ASSERT_GT(parts.rim.size(), 100u);
    // The band along the rim: within 4 pixels of it.
    std::vector<uint8_t> band(size_t(w) * size_t(h), 0);
    for (size_t p : parts.rim)
        for (int dy = -4; dy <= 4; ++dy)
            for (int dx = -4; dx <= 4; ++dx) {
                const int x = int(p % size_t(w)) + dx, y = int(p / size_t(w)) + dy;
                if (x >= 0 && y >= 0 && x < w && y < h) band[size_t(y) * size_t(w) + size_t(x)] = 1;
            }
    auto blobs = [&](const game::ImageRGBA8& img, float contrast) {
        int count = 0;
        for (int y = 4; y < h - 4; ++y)
            for (int x = 4; x < w - 4; ++x) {
                const size_t p = size_t(y) * size_t(w) + size_t(x);
                if (!band[p]) continue;
                const float l = luminance01(img, p);
                bool peak = true;
                double sum = 0.0;
                for (int dy = -4; dy <= 4; ++dy)
                    for (int dx = -4; dx <= 4; ++dx) {
                        const float n = luminance01(img, size_t(y + dy) * size_t(w) + size_t(x + dx));
                        sum += n;
                        if (std::abs(dx) <= 2 && std::abs(dy) <= 2 && (n > l || (n == l && (dy < 0 || (dy == 0 && dx < 0)))))
                            peak = peak && (dx == 0 && dy == 0);
                    }
                count += peak && l - float(sum / 81.0) >= contrast;
            }
        return count;
    };
    effects::WaterPass& pass = stage_->pass<effects::WaterPass>();
    pass.look().rim_drops = false;
    const auto bare = render(water_);
    const int without = blobs(bare, 0.04f);
    pass.look().rim_drops = true;
    const auto img = render(water_);
    maybe_write_png("crown_beads", img);
    const int with = blobs(img, 0.04f);
    std::printf("crown rim: %d bright small blobs along it with its drops, %d without\n", with, without);
    // The rim's own whiteness is beaded by a noise too, which makes some blobs.
    EXPECT_GE(with, 90) << "the crown's rim should be beaded with drops";
    EXPECT_GE(with - without, 35) << "the blobs along the rim should be its drops";
}
