// An energy shot in the real harbour, fired from the car through the sim's input and
// seen side-on by a fixed camera (the replay's chase camera looks along the shot, so
// there it only reads as a ball): the ball just out of the muzzle, the grown beam as a
// long glowing streak, and a beam passing behind the warehouse's corner, cut off where
// the wall is in front. Full frames (every pass of the game's frame) at 640x360 against
// goldens in tests/data/energy_scene; SPINDRIFT_UPDATE_GOLDENS=1 rewrites them and
// SPINDRIFT_ENERGY_SCENE_PNG_DIR=dir writes the frames there too.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "game/capture/FrameCompare.h"
#include "game/capture/ImageFiles.h"
#include "game/replay/InputScript.h"
#include "sim/weapon/Weapon.h"

namespace {

constexpr int kWidth = 640, kHeight = 360;

// The harbour and the game's whole frame, drawn from a camera of the test's choosing.
RenderStage harbour() {
    return RenderStage("harbour", {.width = kWidth, .height = kHeight, .passes = kEveryPass, .environment_size = 64});
}

// Holds `input` for one tick, then nothing for `ticks - 1` more.
void step(RenderStage& stage, sim::TickInput input, int ticks) {
    stage.world().step(input);
    for (int i = 1; i < ticks; ++i) stage.world().step({});
}

// At the sim's time, as the game's renderer draws it.
game::ImageRGBA8 render(RenderStage& stage, const effects::Camera& camera) {
    return stage.render(camera, {.time_s = double(stage.world().tick()) * sim::kTickSeconds});
}

const sim::Shot& shot_of(RenderStage& stage) { return stage.world().get<sim::Weapon>().shots().at(0); }

sim::TickInput fire() {
    sim::TickInput in;
    in.set(sim::Control::Fire, true);
    return in;
}

// The shot's axis from its first segment's start to its last one's head.
struct Path {
    glm::vec3 tail, head;
};
Path path_of(const sim::Shot& s) {
    const sim::EnergySegment& last = s.segments.back();
    return {s.segments.front().start, last.start + last.direction * last.length_m};
}

effects::Camera camera_at(glm::vec3 eye, glm::vec3 target) {
    sim::CameraView v;
    v.eye = eye;
    v.target = target;
    v.fov_y_deg = 50.0f;
    return effects::make_camera(v, float(kWidth) / float(kHeight));
}

// Pixel (top-down rows) and window depth of a world point.
struct Projected {
    glm::vec2 px;
    float depth;
};
Projected project(const effects::Camera& cam, glm::vec3 p) {
    glm::vec4 c = cam.view_proj * glm::vec4(p, 1.0f);
    glm::vec3 ndc = glm::vec3(c) / c.w;
    return {{(ndc.x * 0.5f + 0.5f) * kWidth, (0.5f - ndc.y * 0.5f) * kHeight}, ndc.z * 0.5f + 0.5f};
}

// Points along the shot's segments, their sway included.
std::vector<glm::vec3> along_segments(const sim::Shot& s, int per_segment) {
    std::vector<glm::vec3> points;
    for (const sim::EnergySegment& seg : s.segments)
        for (int i = 0; i < per_segment; ++i)
            points.push_back(seg.start + seg.direction * (seg.length_m * (i + 0.5f) / float(per_segment)));
    return points;
}

bool on_screen(glm::vec2 px) { return px.x >= 0.0f && px.y >= 0.0f && px.x < kWidth && px.y < kHeight; }

// How much brighter the shot made a pixel: the largest channel gain over the frame without it.
int gain(const game::ImageRGBA8& with, const game::ImageRGBA8& without, int x, int y) {
    const size_t i = (size_t(y) * kWidth + x) * 4;
    int g = 0;
    for (int c = 0; c < 3; ++c) g = std::max(g, int(with.pixels[i + c]) - int(without.pixels[i + c]));
    return g;
}

// The spread of the lit pixels: standard deviations along and across their main axis.
struct Spread {
    int count = 0;
    glm::vec2 centre{0.0f}, axis{0.0f};
    float along = 0.0f, across = 0.0f;
};
Spread spread_of(const game::ImageRGBA8& with, const game::ImageRGBA8& without, int threshold) {
    Spread s;
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            if (gain(with, without, x, y) > threshold) {
                ++s.count;
                sx += x, sy += y, sxx += double(x) * x, syy += double(y) * y, sxy += double(x) * y;
            }
    if (s.count < 2) return s;
    const double n = s.count, mx = sx / n, my = sy / n;
    const double cxx = sxx / n - mx * mx, cyy = syy / n - my * my, cxy = sxy / n - mx * my;
    const double mid = 0.5 * (cxx + cyy), d = std::sqrt(0.25 * (cxx - cyy) * (cxx - cyy) + cxy * cxy);
    const double angle = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);
    s.centre = glm::vec2(mx, my);
    s.axis = glm::vec2(std::cos(angle), std::sin(angle));
    s.along = float(std::sqrt(mid + d));
    s.across = float(std::sqrt(std::max(0.0, mid - d)));
    return s;
}

void save(const game::ImageRGBA8& img, const std::string& name) {
    if (const char* dir = std::getenv("SPINDRIFT_ENERGY_SCENE_PNG_DIR")) {
        std::filesystem::create_directories(dir);
        game::write_png(std::filesystem::path(dir) / name, img);
    }
}

void expect_matches_golden(const game::ImageRGBA8& img, const std::string& name) {
    save(img, name);
    const std::filesystem::path golden = std::filesystem::path(SPINDRIFT_TEST_DATA) / "energy_scene" / name;
    if (const char* update = std::getenv("SPINDRIFT_UPDATE_GOLDENS"); update && std::string(update) == "1") {
        std::filesystem::create_directories(golden.parent_path());
        game::write_png(golden, img);
    }
    const game::CompareResult r = game::compare_frames(img, game::read_png(golden));
    EXPECT_TRUE(r.passed) << golden << ": " << r.summary;
}

constexpr int kBallAge = 4, kBeamAge = 31;  // ticks after the fire input
constexpr float kSideOnM = 12.0f;           // the beam camera's distance from the shot's path
constexpr glm::vec3 kCornerEye{-29.0f, 5.0f, -19.0f};  // off the warehouse's door side, by the corner
constexpr int kLit = 40;                    // gain over the frame without the shot, of 255
// A hidden point gains no more than kDark once kBleedPx from the corner's edge (bloom bleeds).
constexpr int kDark = 2, kBleedPx = 20;

class EnergySceneTest : public HeadlessTest {};

// Fired from the car at rest on the shore road, along +x: the ball just out of the
// muzzle, then the beam half a second on, both seen from the warehouse's side of the road.
TEST_F(EnergySceneTest, ShotFromTheCarReadsAsABeamSideOn) {
    RenderStage shot = harbour(), plain = harbour();  // the same harbour, only one with the weapon fired
    step(shot, fire(), kBallAge);
    step(plain, {}, kBallAge);
    const Path ball = path_of(shot_of(shot));
    const glm::vec3 ball_at = 0.5f * (ball.tail + ball.head);
    const effects::Camera ball_cam = camera_at(ball_at + glm::vec3(0.0f, 0.6f, -6.0f), ball_at);
    const game::ImageRGBA8 ball_frame = render(shot, ball_cam), ball_plain = render(plain, ball_cam);

    step(shot, {}, kBeamAge - kBallAge);
    step(plain, {}, kBeamAge - kBallAge);
    ASSERT_FALSE(shot_of(shot).hit());
    const Path beam = path_of(shot_of(shot));
    const glm::vec3 mid = 0.5f * (beam.tail + beam.head);
    const effects::Camera beam_cam = camera_at(mid + glm::vec3(0.0f, 5.0f, -kSideOnM), mid);
    const game::ImageRGBA8 beam_frame = render(shot, beam_cam), beam_plain = render(plain, beam_cam);
    save(ball_plain, "ball_plain.png");
    save(beam_plain, "beam_plain.png");

    // The ball lights a round patch where it is.
    const Spread b = spread_of(ball_frame, ball_plain, kLit);
    std::printf("ball: %d pixels lit, sd %.1f x %.1f px\n", b.count, b.along, b.across);
    EXPECT_GT(b.count, 1000);
    EXPECT_LT(b.along, 1.6f * b.across);
    // Its light on the road below pulls the patch's centre down a little.
    EXPECT_LT(glm::distance(b.centre, project(ball_cam, ball_at).px), b.across);
    const glm::ivec2 ball_px(project(ball_cam, ball_at).px);
    const uint8_t* core = &ball_frame.pixels[(size_t(ball_px.y) * kWidth + ball_px.x) * 4];
    EXPECT_GT(std::min({core[0], core[1], core[2]}), 215) << "a white core";

    // The beam lights a streak along its projected path, several times longer than wide,
    // from its tail to its head.
    const Spread s = spread_of(beam_frame, beam_plain, kLit);
    const glm::vec2 tail_px = project(beam_cam, beam.tail).px, head_px = project(beam_cam, beam.head).px;
    const glm::vec2 path_dir = glm::normalize(head_px - tail_px);
    const float path_px = glm::distance(tail_px, head_px), extent_px = s.along * std::sqrt(12.0f);
    std::printf("beam: %d pixels lit, sd %.1f x %.1f px, extent %.0f px along a %.0f px path, axis off it by %.2f deg\n",
                s.count, s.along, s.across, extent_px, path_px,
                glm::degrees(std::acos(std::min(1.0f, std::fabs(glm::dot(s.axis, path_dir))))));
    EXPECT_GT(path_px, 0.6f * kWidth);  // side-on: the beam is seen at nearly its full length
    EXPECT_GT(s.along, 4.0f * s.across);
    EXPECT_GT(std::fabs(glm::dot(s.axis, path_dir)), std::cos(glm::radians(3.0f)));
    EXPECT_GT(extent_px, 0.9f * path_px);
    EXPECT_LT(glm::distance(s.centre, 0.5f * (tail_px + head_px)), 0.1f * path_px);
    // White along its core, blue in the glow around it.
    int white = 0;
    const std::vector<glm::vec3> axis = along_segments(shot_of(shot), 16);
    for (const glm::vec3& p : axis) {
        const glm::ivec2 px(project(beam_cam, p).px);
        const uint8_t* c = &beam_frame.pixels[(size_t(px.y) * kWidth + px.x) * 4];
        white += std::min({c[0], c[1], c[2]}) > 215;
    }
    glm::dvec3 glow(0.0);
    int glow_count = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const int g = gain(beam_frame, beam_plain, x, y);
            if (g <= kLit || g > 120) continue;
            const size_t i = (size_t(y) * kWidth + x) * 4;
            for (int c = 0; c < 3; ++c) glow[c] += int(beam_frame.pixels[i + c]) - int(beam_plain.pixels[i + c]);
            ++glow_count;
        }
    glow /= double(std::max(glow_count, 1));
    std::printf("beam: %d of %zu axis points white; glow gain r %.0f g %.0f b %.0f over %d pixels\n", white,
                axis.size(), glow.x, glow.y, glow.z, glow_count);
    EXPECT_GT(white, int(axis.size()) * 3 / 4);
    EXPECT_GT(glow.z, 1.5 * glow.x);
    expect_matches_golden(ball_frame, "ball_side_on.png");
    expect_matches_golden(beam_frame, "beam_side_on.png");
}

// The replay's shot past the warehouse's right corner (replays/harbour_energy.script's
// drive up to it), half a second after firing, from beside the warehouse's door: the
// corner stands in front of the beam's far end and hides it.
TEST_F(EnergySceneTest, WarehouseCornerCutsTheBeamOff) {
    constexpr const char* kDrive = "0 hold throttle\n40 hold throttle steer_left\n165 hold throttle\n"
                                   "180 hold throttle steer_left\n196 hold brake\n";
    const game::InputScript drive = game::parse_script(std::string(kDrive) + "201 end\n", "drive");
    constexpr uint32_t kFireTick = 170;
    RenderStage shot = harbour(), plain = harbour();
    for (uint32_t t = 0; t < drive.end_tick; ++t) {
        sim::TickInput in = drive.inputs[t];
        plain.world().step(in);
        in.set(sim::Control::Fire, t == kFireTick);
        shot.world().step(in);
    }
    ASSERT_FALSE(shot_of(shot).hit());
    const Path beam = path_of(shot_of(shot));
    std::printf("corner beam: tail %.1f %.1f %.1f head %.1f %.1f %.1f age %u\n", beam.tail.x, beam.tail.y, beam.tail.z,
                beam.head.x, beam.head.y, beam.head.z, shot_of(shot).age_ticks);
    const glm::vec3 mid = 0.5f * (beam.tail + beam.head);
    const effects::Camera cam = camera_at(kCornerEye, mid);
    const game::ImageRGBA8 frame = render(shot, cam);
    const std::vector<float> depth = shot.depth();
    const game::ImageRGBA8 without = render(plain, cam);
    save(without, "corner_plain.png");
    // Where the opaque scene is nearer than the beam, the beam is hidden; elsewhere it shows.
    struct Sample {
        glm::ivec2 px;
        bool hidden;
    };
    std::vector<Sample> samples;
    for (const glm::vec3& p : along_segments(shot_of(shot), 32)) {
        const Projected q = project(cam, p);
        if (!on_screen(q.px)) continue;
        const glm::ivec2 px(q.px);
        samples.push_back({px, depth[size_t(px.y) * kWidth + px.x] < q.depth});
    }
    int visible = 0, visible_lit = 0, hidden = 0, hidden_dark = 0, worst_hidden_gain = 0;
    for (const Sample& a : samples) {
        const int g = gain(frame, without, a.px.x, a.px.y);
        if (!a.hidden) {
            ++visible;
            visible_lit += g > kLit;
            continue;
        }
        // Bloom bleeds a little light over the corner's edge: judge hidden points away from it.
        float to_visible = 1e9f;
        for (const Sample& b : samples)
            if (!b.hidden) to_visible = std::min(to_visible, glm::distance(glm::vec2(a.px), glm::vec2(b.px)));
        if (to_visible < kBleedPx) continue;
        ++hidden;
        hidden_dark += g <= kDark;
        worst_hidden_gain = std::max(worst_hidden_gain, g);
    }
    std::printf("corner: %d of %d visible axis points lit, %d of %d hidden ones dark (worst gain %d)\n", visible_lit,
                visible, hidden_dark, hidden, worst_hidden_gain);
    EXPECT_GT(visible, 30);
    EXPECT_GT(hidden, 15);
    EXPECT_EQ(visible_lit, visible);
    EXPECT_EQ(hidden_dark, hidden);
    expect_matches_golden(frame, "beam_behind_warehouse.png");
}

}  // namespace
