// The sun's shadow on a real headless context: a lit hill with nothing between it and a
// low sun is not darkened by its own shadow map anywhere it faces the sun (no shadow
// acne: the stripes a surface draws when it shadows itself), and the car's shadow on the
// road starts at the car (no gap under it: the bias does not lift the shadow off).
// SPINDRIFT_SHADOW_PNG_DIR=dir writes the frames there to look at.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "effects/scene/ShadowPass.h"
#include "SimTestLevel.h"
#include "game/capture/ImageFiles.h"
#include "game/capture/Readback.h"
#include "sim/world/Terrain.h"

namespace {

constexpr int W = 320, H = 180;

void maybe_write(const std::string& name, const game::ImageRGBA8& image) {
    const char* dir = std::getenv("SPINDRIFT_SHADOW_PNG_DIR");
    if (dir && *dir) game::write_png(std::filesystem::path(dir) / (name + ".png"), image);
}

class ShadowRenderTest : public HeadlessTest {};

// The stage's scene colour with the shadow map as the shadow pass leaves it, and with
// it cleared to the far plane afterwards (nothing casts a shadow); luma of each.
struct ShadowedAndOpen {
    std::vector<float> shadowed, open, normals;  // normals: xyz per pixel
    std::vector<glm::vec3> positions;             // world, from depth; rows top-down
    game::ImageRGBA8 image;
};

float luma(const float* rgb) { return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2]; }

ShadowedAndOpen render_both(RenderStage& stage, const sim::CameraView& view) {
    ShadowedAndOpen r;
    stage.targets().write_normals(true);  // read below; off unless asked
    r.image = stage.render(view);
    const game::ImageRGBA32F shadowed = stage.hdr();
    const auto normals = game::read_framebuffer_rgba32f(stage.targets().hdr().id(), GL_COLOR_ATTACHMENT1, W, H);
    const std::vector<float> depth = stage.depth();
    const effects::Camera camera = stage.camera(view);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const glm::vec4 ndc((float(x) + 0.5f) / W * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / H * 2.0f,
                                depth[size_t(y * W + x)] * 2.0f - 1.0f, 1.0f);
            const glm::vec4 p = camera.inv_view_proj * ndc;
            r.positions.push_back(glm::vec3(p) / p.w);
        }
    StageFrame open;
    open.replaced = kShadowPass;
    open.replacement = [&](const effects::FrameContext& frame) {
        stage.pass<effects::ShadowPass>().render(frame);
        const float far = 1.0f;
        glClearTexImage(stage.lighting().shadow_map.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &far);
    };
    stage.render(view, open);
    const game::ImageRGBA32F unshadowed = stage.hdr();
    for (size_t i = 0; i < size_t(W * H); ++i) {
        r.shadowed.push_back(luma(&shadowed.pixels[i * 4]));
        r.open.push_back(luma(&unshadowed.pixels[i * 4]));
        for (int c = 0; c < 3; ++c) r.normals.push_back(normals.pixels[i * 4 + size_t(c)]);
    }
    return r;
}

// Whether the ray from p to the sun clears the terrain with room to spare (marched in
// 0.25 m steps): near the edge of the hill's real shadow the filter's soft edge darkens
// a little, rightly.
bool sees_sun(const sim::Terrain& terrain, glm::vec3 p, glm::vec3 sun) {
    for (float t = 0.25f; t < 120.0f; t += 0.25f) {
        const glm::vec3 q = p + sun * t;
        if (q.y < terrain.ground_height({q.x, q.z}) + std::min(0.5f, 0.05f * t)) return false;
    }
    return true;
}

}  // namespace

TEST_F(ShadowRenderTest, ALitHillUnderALowSunDoesNotShadowItself) {
    sim::LevelDesc level = make_test_level();
    level.hills.push_back({{-40.0f, -60.0f}, 14.0f, 9.0f});
    RenderStage stage(level, {.width = W, .height = H, .passes = kLitScene | kTonemapPass});
    // A low sun from +x: the hill's sunlit side is seen from the sun's side, its slopes
    // meeting the light at every angle down to grazing.
    const glm::vec3 sun = glm::normalize(glm::vec3(1.0f, 0.3f, 0.15f));
    effects::SkyState sky = stage.sky();
    sky.sun_dir = sun;
    stage.set_sky(sky);
    sim::CameraView view;
    view.eye = {0.0f, 12.0f, -40.0f};
    view.target = {-40.0f, 5.0f, -60.0f};
    const ShadowedAndOpen r = render_both(stage, view);
    maybe_write("lit_hill", r.image);

    int lit = 0, darkened = 0;
    double worst = 1.0;
    for (size_t i = 0; i < size_t(W * H); ++i) {
        const glm::vec3 n(r.normals[i * 3], r.normals[i * 3 + 1], r.normals[i * 3 + 2]);
        if (glm::dot(n, n) < 0.5f) continue;  // sky
        const float nl = glm::dot(glm::normalize(n), sun);
        if (nl < 0.1f) continue;  // turned away: lit only by the filter's soft edge
        if (!sees_sun(stage.world().terrain(), r.positions[i], sun)) continue;  // the hill's real shadow
        if (glm::distance(r.positions[i], view.eye) > 60.0f) continue;  // the hill, not the shore's far edge
        ++lit;
        const double ratio = r.shadowed[i] / std::max(r.open[i], 1e-6f);
        worst = std::min(worst, ratio);
        if (ratio < 0.98) ++darkened;
    }
    ASSERT_GT(lit, W * H / 10) << "the sunlit slope fills a good part of the frame";
    EXPECT_EQ(darkened, 0) << "of " << lit << " sunlit pixels; the darkest at " << worst << " of its unshadowed light";
}

namespace {

// Where the ray from world point p towards the sun passes the box [lo, hi] (model space
// of `model`): the largest distance outside it on any axis, negative inside.
float ray_box_gap(glm::vec3 p, glm::vec3 sun, const glm::mat4& model, glm::vec3 lo, glm::vec3 hi) {
    const glm::mat4 to_model = glm::inverse(model);
    const glm::vec3 o = glm::vec3(to_model * glm::vec4(p, 1.0f));
    const glm::vec3 d = glm::vec3(to_model * glm::vec4(sun, 0.0f));
    float best = 1e9f;
    for (float t = 0.0f; t < 20.0f; t += 0.02f) {
        const glm::vec3 q = o + d * t;
        const glm::vec3 out = glm::max(lo - q, q - hi);
        best = std::min(best, std::max(out.x, std::max(out.y, out.z)));
    }
    return best;
}

}  // namespace

// The car standing on the harbour road, seen low from the side its shadow falls on:
// road pixels whose ray to the sun goes through the core of the car's body are in
// shadow (the bias does not lift the shadow off the road under it), and road pixels
// whose ray passes well clear of the car are fully lit (no acne on the road).
TEST_F(ShadowRenderTest, TheCarsShadowStartsAtTheCarAndNothingElseIsDark) {
    RenderStage stage("harbour", {.width = W, .height = H, .passes = kLitScene | kTonemapPass});
    const sim::Pose car = effects::capture_poses(stage.world()).car;
    const glm::vec3 sun = stage.sky().sun_dir;
    const effects::Model& model = stage.resources().desc.models[size_t(stage.resources().desc.car_model)];
    const glm::vec3 lo = model.bounds_min, hi = model.bounds_max, size = hi - lo;
    // The body's core: all but the rounded ends and sides of its length and width, from
    // just above the wheels' bottom third to below the roof.
    const glm::vec3 core_lo = lo + size * glm::vec3(0.15f, 0.3f, 0.15f), core_hi = hi - size * glm::vec3(0.15f, 0.15f, 0.15f);
    sim::CameraView view;
    const glm::vec3 side = -glm::normalize(glm::vec3(sun.x, 0.0f, sun.z));
    view.eye = car.position + side * 5.0f + glm::vec3(0.0f, 1.2f, 0.0f) - car.forward_flat() * 2.0f;
    view.target = car.position + side * 1.2f;
    const ShadowedAndOpen r = render_both(stage, view);
    maybe_write("car_shadow", r.image);

    int core = 0, core_lit = 0, clear = 0, clear_dark = 0;
    for (size_t i = 0; i < size_t(W * H); ++i) {
        const glm::vec3 n(r.normals[i * 3], r.normals[i * 3 + 1], r.normals[i * 3 + 2]);
        const glm::vec3 p = r.positions[i];
        if (n.y < 0.95f || std::abs(p.y - stage.world().terrain().ground_height({p.x, p.z})) > 0.05f) continue;
        // Near the car: a lamp post's shadow falls a few metres further off.
        if (glm::distance(glm::vec2(p.x, p.z), glm::vec2(car.position.x, car.position.z)) > 4.0f) continue;
        const double ratio = r.shadowed[i] / std::max(r.open[i], 1e-6f);
        if (ray_box_gap(p, sun, car.matrix(), core_lo, core_hi) < 0.0f) {
            ++core;
            if (ratio > 0.6) ++core_lit;
        } else if (ray_box_gap(p, sun, car.matrix(), lo, hi) > 0.4f) {
            ++clear;
            if (ratio < 0.98) ++clear_dark;
        }
    }
    ASSERT_GT(core, 50) << "the core's shadow is in view";
    ASSERT_GT(clear, 300) << "open road is in view";
    // A slope-scaled polygon offset in the shadow pass lit 5% of them, in streaks.
    EXPECT_LE(core_lit, core / 100) << "of " << core << " road pixels behind the car's body";
    EXPECT_EQ(clear_dark, 0) << "of " << clear << " road pixels with nothing between them and the sun";
}

// The shadow map starts each frame from the still casters' map and restores only where
// the last frame's moving casters drew: after the car has driven on, the map is the very
// one a fresh renderer (a whole copy) draws for the same world.
TEST_F(ShadowRenderTest, AfterTheCarMovesTheMapIsTheOneAFreshRendererDraws) {
    auto drive_on = [](sim::World& world, int ticks) {
        for (int t = 0; t < ticks; ++t) {
            sim::TickInput in;
            in.set(sim::Control::Throttle, true);
            in.set(sim::Control::SteerLeft, t > 40);
            world.step(in);
        }
    };
    auto shadow_map = [](RenderStage& stage) {
        const effects::gl::Texture& map = stage.lighting().shadow_map;
        std::vector<float> depth(size_t(map.width()) * size_t(map.height()));
        glGetTextureImage(map.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * sizeof(float)), depth.data());
        return depth;
    };
    sim::CameraView view;  // held still, so the sun's view (and the still map) stays put
    RenderStage moved("harbour", {.width = W, .height = H, .passes = kLitScene});
    const glm::vec3 start = effects::capture_poses(moved.world()).car.position;
    view.eye = start + glm::vec3(0.0f, 30.0f, 20.0f);
    view.target = start;
    moved.render(view);
    const std::vector<float> before = shadow_map(moved);
    drive_on(moved.world(), 150);
    ASSERT_GT(glm::distance(effects::capture_poses(moved.world()).car.position, start), 5.0f);
    moved.render(view);
    const std::vector<float> after = shadow_map(moved);

    RenderStage fresh("harbour", {.width = W, .height = H, .passes = kLitScene});
    drive_on(fresh.world(), 150);
    fresh.render(view);
    const std::vector<float> expected = shadow_map(fresh);
    ASSERT_EQ(after.size(), expected.size());
    EXPECT_NE(before, after) << "the car's shadow moved";
    size_t differ = 0;
    for (size_t i = 0; i < after.size(); ++i) differ += after[i] != expected[i];
    EXPECT_EQ(differ, 0u) << "of " << after.size() << " texels";
}
