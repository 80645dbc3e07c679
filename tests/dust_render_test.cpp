// The dust pass on a real headless context, over the harbour's warehouse props: the
// dust shows on tops and not under the shelf's boards, a cleared patch shows, fins
// change grazing views, shells thin out with distance, the coarse level far away looks
// like the fine one, and a close-up of the crates matches its golden in
// tests/data/dust. SPINDRIFT_UPDATE_GOLDENS=1 rewrites the golden;
// SPINDRIFT_DUST_PNG_DIR=dir writes the frames there too.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <unistd.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "effects/dust/DustPass.h"
#include "game/capture/FrameCompare.h"
#include "game/capture/ImageFiles.h"
#include "sim/dust/DustField.h"

namespace {

constexpr int kWidth = 320, kHeight = 200;

// The harbour's lit scene, its dust shells and the tonemap, from a camera of the test's choosing.
const StagePasses kDustFrame = kLitScene | kDustPass | kTonemapPass;
const StageFrame kWithoutDust{.skip = kDustPass};

RenderStage dust_stage(const std::string& level = "harbour", int w = kWidth, int h = kHeight,
                       StagePasses passes = kDustFrame) {
    return RenderStage(level, {.width = w, .height = h, .passes = passes});
}

sim::DustField& field(RenderStage& stage) { return stage.world().get<sim::DustField>(); }

glm::ivec2 pixel_of(const sim::CameraView& view, glm::vec3 p) {
    effects::Camera camera = effects::make_camera(view, float(kWidth) / float(kHeight));
    glm::vec4 c = camera.view_proj * glm::vec4(p, 1.0f);
    glm::vec2 ndc = glm::vec2(c) / c.w;
    return {int((ndc.x * 0.5f + 0.5f) * kWidth), int((0.5f - ndc.y * 0.5f) * kHeight)};
}

void save(const game::ImageRGBA8& img, const std::string& name) {
    if (const char* dir = std::getenv("SPINDRIFT_DUST_PNG_DIR")) game::write_png(std::filesystem::path(dir) / name, img);
}

// Mean and spread of the luminance over a window, and the fraction of its pixels that
// differ from a base image.
struct WindowStats {
    double luma = 0.0, changed = 0.0, luma_sd = 0.0;
};
WindowStats stats(const game::ImageRGBA8& img, const game::ImageRGBA8* base, glm::ivec2 c, int half) {
    WindowStats s;
    int n = 0;
    for (int y = std::max(c.y - half, 0); y <= std::min(c.y + half, img.height - 1); ++y)
        for (int x = std::max(c.x - half, 0); x <= std::min(c.x + half, img.width - 1); ++x) {
            const uint8_t* p = &img.pixels[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
            double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            s.luma += l;
            s.luma_sd += l * l;
            if (base) {
                const uint8_t* q = &base->pixels[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
                s.changed += (std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2])) > 12;
            }
            ++n;
        }
    s.luma /= n;
    s.luma_sd = std::sqrt(std::max(s.luma_sd / n - s.luma * s.luma, 0.0));
    s.changed /= n;
    return s;
}

// Close over the big crates, looking down at their tops.
sim::CameraView crate_view() {
    sim::CameraView v;
    v.eye = {-47.6f, 3.6f, -44.0f};
    v.target = {-49.6f, 2.3f, -46.0f};
    v.fov_y_deg = 50.0f;
    return v;
}

// Half a metre over the second large crate's top, looking down across it to the
// small crate standing on the first: close enough to see single fibres.
sim::CameraView close_view() {
    sim::CameraView v;
    v.eye = {-48.5f, 2.95f, -45.7f};
    v.target = {-49.2f, 2.43f, -46.4f};
    v.fov_y_deg = 45.0f;
    return v;
}

}  // namespace

class DustRenderTest : public HeadlessTest {};

TEST_F(DustRenderTest, DustShowsOnTopsAndAClearedPatchShowsTheCrate) {
    RenderStage stage = dust_stage();
    const sim::CameraView view = crate_view();
    game::ImageRGBA8 bare = stage.render(view, kWithoutDust), dusty = stage.render(view);
    save(bare, "crates_bare.png");
    save(dusty, "crates_dusty.png");
    // The second large crate's top: covered, and lighter than the dark pine.
    const glm::vec3 top{-49.1f, 2.43f, -46.3f};
    const glm::ivec2 at = pixel_of(view, top);
    ASSERT_TRUE(at.x > 20 && at.x < kWidth - 20 && at.y > 20 && at.y < kHeight - 20) << at.x << "," << at.y;
    WindowStats b = stats(bare, nullptr, at, 8), d = stats(dusty, &bare, at, 8);
    EXPECT_GT(d.changed, 0.6) << "most of the crate top is covered";
    EXPECT_GT(d.luma_sd, b.luma_sd + 2.0) << "fibres and bumps, not a flat coat";
    EXPECT_GT(b.luma, 10.0) << "the crate is lit, not black";

    // Blow the dust off a patch of that top: the crate shows through again there.
    field(stage).clear_along(top + glm::vec3(0.0f, 0.2f, 0.0f), top + glm::vec3(0.0f, 0.2f, 0.0f), 0.5f);
    game::ImageRGBA8 cleared = stage.render(view);
    save(cleared, "crates_cleared.png");
    WindowStats c = stats(cleared, &bare, at, 4);
    EXPECT_LT(c.changed, 0.15);
    EXPECT_NEAR(c.luma, stats(bare, nullptr, at, 4).luma, 6.0);
}

TEST_F(DustRenderTest, FinsChangeGrazingViewsAndShellsThinOutWithDistance) {
    RenderStage stage = dust_stage();
    effects::DustPass& dust = stage.pass<effects::DustPass>();
    sim::CameraView grazing;
    grazing.eye = {-49.1f, 2.47f, -44.4f};  // just above the crate top, looking across it
    grazing.target = {-49.1f, 2.43f, -46.3f};
    grazing.fov_y_deg = 40.0f;
    game::ImageRGBA8 bare = stage.render(grazing, kWithoutDust);
    game::ImageRGBA8 with_fins = stage.render(grazing);
    dust.fins_enabled() = false;
    game::ImageRGBA8 without_fins = stage.render(grazing);
    save(with_fins, "grazing_fins.png");
    save(without_fins, "grazing_no_fins.png");
    const glm::ivec2 at = pixel_of(grazing, {-49.1f, 2.44f, -46.3f});
    EXPECT_GT(stats(with_fins, &without_fins, at, 30).changed, 0.02);
    EXPECT_GT(stats(with_fins, &bare, at, 30).changed, 0.05);

    EXPECT_EQ(dust.shells_at(1.0f), dust.lod().max_shells);
    EXPECT_GT(dust.shells_at(2.0f), dust.shells_at(10.0f));
    EXPECT_EQ(dust.shells_at(500.0f), dust.lod().min_shells);
    // Fins only where the stack is tall enough on screen for its shells to show as lines.
    dust.fins_enabled() = true;
    EXPECT_TRUE(dust.fins_at(dust.lod().fin_min_px));
    EXPECT_FALSE(dust.fins_at(0.5f * dust.lod().fin_min_px));
}

// Looking down on the crates and the shelf from 6 m and more, every prop beyond
// coarse_from_m: the coarse level must cover what the sim's tessellation covers, in
// the same tone.
TEST_F(DustRenderTest, FromSixMetresTheCoarseLevelLooksLikeTheFineOne) {
    constexpr int W = 640, H = 360;
    RenderStage stage = dust_stage("harbour", W, H);
    effects::DustPass& dust = stage.pass<effects::DustPass>();
    sim::CameraView view;
    view.eye = {-44.0f, 6.5f, -41.0f};
    view.target = {-46.0f, 2.2f, -47.0f};
    view.fov_y_deg = 60.0f;
    const game::ImageRGBA8 bare = stage.render(view, kWithoutDust), coarse = stage.render(view);
    for (const sim::DustPropRange& prop : field(stage).surface().props()) {
        const float d = glm::length(view.eye - glm::clamp(view.eye, prop.bounds.min, prop.bounds.max));
        EXPECT_EQ(dust.level_at(d), 1) << prop.name << " at " << d << " m";
    }
    EXPECT_LT(dust.geometry().dusty_triangles(1) * 3, dust.geometry().dusty_triangles(0));
    const float coarse_from = dust.lod().coarse_from_m;
    dust.lod().coarse_from_m = 1000.0f;
    const game::ImageRGBA8 fine = stage.render(view);
    dust.lod().coarse_from_m = coarse_from;
    save(coarse, "view_coarse.png");
    save(fine, "view_fine.png");
    // Around each prop in view: how much the dust changed, and how bright it is there.
    const effects::Camera camera = effects::make_camera(view, float(W) / float(H));
    int seen = 0;
    for (const sim::DustPropRange& prop : field(stage).surface().props()) {
        const glm::vec4 clip = camera.view_proj * glm::vec4(prop.centre(), 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        if (clip.w <= 0.0f || std::abs(ndc.x) > 0.9f || std::abs(ndc.y) > 0.9f) continue;
        const glm::ivec2 at{int((ndc.x * 0.5f + 0.5f) * W), int((0.5f - ndc.y * 0.5f) * H)};
        const WindowStats f = stats(fine, &bare, at, 12), c = stats(coarse, &bare, at, 12);
        if (f.changed < 0.05) continue;  // too little of its dust faces the eye
        ++seen;
        EXPECT_NEAR(c.changed, f.changed, 0.2 * f.changed) << prop.name;
        EXPECT_NEAR(c.luma, f.luma, 3.0) << prop.name;
    }
    EXPECT_GE(seen, 3) << "the three crates show their dust";
}

TEST_F(DustRenderTest, UnderTheShelfBoardsThereIsLittleDust) {
    RenderStage stage = dust_stage();
    sim::CameraView v;
    v.eye = {-39.6f, 3.9f, -46.6f};
    v.target = {-40.0f, 2.3f, -49.35f};
    v.fov_y_deg = 55.0f;
    game::ImageRGBA8 bare = stage.render(v, kWithoutDust), dusty = stage.render(v);
    save(bare, "shelf_bare.png");
    save(dusty, "shelf_dusty.png");
    sim::DustField& f = field(stage);
    const float top = f.amount_near({-40.0f, 2.88f, -49.35f}), middle = f.amount_near({-40.0f, 2.18f, -49.4f});
    EXPECT_GT(top, 0.6f);
    EXPECT_LT(middle, 0.6f * top);
    // The top board is covered on screen; the dust changed it.
    EXPECT_GT(stats(dusty, &bare, pixel_of(v, {-40.0f, 2.88f, -49.12f}), 2).changed, 0.5);
}

TEST_F(DustRenderTest, SandAndMouldPresetsComeFromTheSameMachinery) {
    // The harbour with its crates under sand and the small crate under mould.
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("spindrift_dust_presets_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path data = fs::path(SPINDRIFT_TEST_DATA).parent_path().parent_path() / "levels";
    std::ifstream in(data / "harbour.json");
    std::string json{std::istreambuf_iterator<char>(in), {}};
    auto swap = [&](const std::string& from, const std::string& to) {
        for (size_t at = json.find(from); at != std::string::npos; at = json.find(from, at + to.size())) json.replace(at, from.size(), to);
    };
    swap("\"crate_large.gltf\", \"dust\": true", "\"crate_large.gltf\", \"dust\": \"sand\"");
    swap("\"crate_small.gltf\", \"dust\": true", "\"crate_small.gltf\", \"dust\": \"mould\"");
    std::ofstream(dir / "presets.json") << json;
    fs::create_directory_symlink(data / "harbour", dir / "presets");
    game::ImageRGBA8 dust, sand;
    glm::vec3 small_top{0.0f};
    {
        RenderStage stage = dust_stage();
        dust = stage.render(crate_view());
    }
    {
        RenderStage stage = dust_stage((dir / "presets.json").string());
        sand = stage.render(crate_view());
        save(sand, "crates_sand_mould.png");
        EXPECT_EQ(field(stage).surface().props()[0].kind, sim::DustKind::Sand);
        const sim::DustPropRange& small = field(stage).surface().props()[2];
        EXPECT_EQ(small.kind, sim::DustKind::Mould);
        small_top = {small.centre().x, small.bounds.max.y, small.centre().z};
        // Sand slides off anything steeper than its angle of repose: the crate sides
        // hold none even where dust would lie thinly.
        const auto& s = field(stage).surface();
        for (uint32_t v = 0; v < s.props()[0].vertex_count; v += 7) {
            if (s.normals()[s.props()[0].first_vertex + v].y < 0.7f) {
                EXPECT_EQ(field(stage).amounts()[s.props()[0].first_vertex + v], 0.0f);
            }
        }
    }
    fs::remove_all(dir);
    const glm::ivec2 at = pixel_of(crate_view(), {-49.1f, 2.43f, -46.3f});
    EXPECT_GT(stats(sand, &dust, at, 8).changed, 0.5) << "sand looks unlike dust";
    const glm::ivec2 small_at = pixel_of(crate_view(), small_top);
    ASSERT_TRUE(small_at.x > 6 && small_at.x < kWidth - 6 && small_at.y > 6 && small_at.y < kHeight - 6)
        << small_at.x << "," << small_at.y;
    const WindowStats mould = stats(sand, &dust, small_at, 3);
    EXPECT_GT(mould.changed, 0.5) << "mould looks unlike dust";
    EXPECT_LT(mould.luma, stats(dust, nullptr, small_at, 3).luma) << "mould is darker than dust";
}

// The README's close-up: a frame check against tests/data/dust/crates_closeup.png at
// 640x360, so a change to the fibres, shells or their light shows as a failure here.
TEST_F(DustRenderTest, CloseUpOfTheCratesMatchesItsGolden) {
    constexpr int W = 640, H = 360;
    RenderStage stage = dust_stage("harbour", W, H);
    const game::ImageRGBA8 bare = stage.render(close_view(), kWithoutDust), dusty = stage.render(close_view());
    save(dusty, "crates_closeup.png");
    // Most of the frame is the dusty crate top, and it is not a flat coat.
    const WindowStats d = stats(dusty, &bare, {W / 2, H / 2}, 60);
    EXPECT_GT(d.changed, 0.6);
    EXPECT_GT(d.luma_sd, 4.0);
    const std::filesystem::path golden = std::filesystem::path(SPINDRIFT_TEST_DATA) / "dust" / "crates_closeup.png";
    if (const char* update = std::getenv("SPINDRIFT_UPDATE_GOLDENS"); update && std::string(update) == "1") {
        std::filesystem::create_directories(golden.parent_path());
        game::write_png(golden, dusty);
    }
    const game::CompareResult r = game::compare_frames(dusty, game::read_png(golden));
    EXPECT_TRUE(r.passed) << golden << ": " << r.summary;
}

// Inside the warehouse the floor loses the sky's blue ambient light to its roof; out
// on the shore road, away from every prop, nothing changes.
TEST_F(DustRenderTest, UnderTheWarehouseRoofTheSkyLightGoesAndOutsideNothingChanges) {
    RenderStage roofed_stage = dust_stage();
    RenderStage open_sky = dust_stage("harbour", kWidth, kHeight, kDustFrame & ~kSkyOcclusionPass);
    sim::CameraView floor;
    floor.eye = {-36.0f, 2.5f, -33.0f};
    floor.target = {-40.0f, 1.2f, -38.0f};
    floor.fov_y_deg = 50.0f;
    sim::CameraView road;
    road.eye = {-80.0f, 4.0f, -30.0f};
    road.target = {-80.0f, 1.0f, -10.0f};
    road.fov_y_deg = 50.0f;
    const game::ImageRGBA8 roofed = roofed_stage.render(floor, kWithoutDust),
                           unroofed = open_sky.render(floor, kWithoutDust);
    save(roofed, "sky_occlusion_floor.png");
    save(unroofed, "sky_occlusion_floor_open.png");
    auto blueness = [](const game::ImageRGBA8& img) {  // blue over red, the lower half
        double b = 0.0, r = 0.0;
        for (size_t i = img.pixels.size() / 2; i < img.pixels.size(); i += 4) {
            r += img.pixels[i];
            b += img.pixels[i + 2];
        }
        return b / std::max(r, 1.0);
    };
    const glm::ivec2 centre(kWidth / 2, 3 * kHeight / 4);
    EXPECT_LT(stats(roofed, nullptr, centre, 30).luma, 0.8 * stats(unroofed, nullptr, centre, 30).luma);
    EXPECT_LT(blueness(roofed), 1.2);
    EXPECT_GT(blueness(unroofed), 1.5);
    const game::ImageRGBA8 outside = roofed_stage.render(road, kWithoutDust),
                           outside_open = open_sky.render(road, kWithoutDust);
    save(outside, "sky_occlusion_road.png");
    const game::CompareResult same = game::compare_frames(outside, outside_open);
    EXPECT_TRUE(same.passed) << same.summary;
}

