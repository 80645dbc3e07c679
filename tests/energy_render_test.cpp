// The energy pass on a real headless context: the shader's H against an independent
// quadrature of the same field, no NaN or Inf for any ray (through a segment's start,
// along its axis, parallel to it, from inside it), and the seed's six orderings of
// camera, beam and geometry as frame checks against goldens in tests/data/energy.
// SPINDRIFT_UPDATE_GOLDENS=1 rewrites the goldens; SPINDRIFT_ENERGY_PNG_DIR=dir writes
// the frames there too.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "SimTestLevel.h"
#include "effects/energy/EnergyPass.h"
#include "effects/energy/EnergyProbe.h"
#include "game/capture/Readback.h"
#include "sim/weapon/Weapon.h"
#include "game/capture/FrameCompare.h"
#include "game/capture/ImageFiles.h"
#include "sim/core/Rng.h"
#include "sim/weapon/EnergyField.h"

namespace {

using sim::EnergySegment;

EnergySegment segment(glm::vec3 start, glm::vec3 dir, float length, float strength, float radius) {
    return {start, glm::normalize(dir), length, strength, strength, radius};
}

effects::Camera look(glm::vec3 eye, glm::vec3 target, int width, int height) {
    sim::CameraView v;
    v.eye = eye;
    v.target = target;
    v.fov_y_deg = 60.0f;
    return effects::make_camera(v, float(width) / float(height));
}

// The view ray of pixel (x, y) (GL rows), in double, as the shader makes it.
glm::dvec3 ray_direction(const effects::Camera& cam, int x, int y, int width, int height) {
    glm::dvec4 ndc((x + 0.5) / width * 2.0 - 1.0, (y + 0.5) / height * 2.0 - 1.0, 1.0, 1.0);
    glm::dvec4 p = glm::dmat4(cam.inv_view_proj) * ndc;
    return glm::normalize(glm::dvec3(p) / p.w - glm::dvec3(cam.eye));
}

// Window depth of a world point.
float window_depth(const effects::Camera& cam, glm::vec3 p) {
    glm::vec4 clip = cam.view_proj * glm::vec4(p, 1.0f);
    return clip.z / clip.w * 0.5f + 0.5f;
}

class EnergyRenderTest : public HeadlessTest {
protected:
    effects::EnergyPass pass;
};
TEST_F(EnergyRenderTest, ClosedFormMatchesQuadratureAwayFromTheSingularPoints) {
    constexpr int W = 64, H = 48;
    effects::EnergyProbe probe(W, H);
    const effects::Camera cam = look({0.5f, 1.5f, 8.0f}, {0.0f, 0.5f, 0.0f}, W, H);
    const std::vector<EnergySegment> segs = {
        segment({-4.0f, 0.5f, 0.0f}, {1.0f, 0.0f, 0.0f}, 5.0f, 0.12f, 1.6f),
        segment({1.0f, 0.5f, 0.0f}, {1.0f, 0.3f, -0.5f}, 4.0f, 0.10f, 1.2f),
        segment({-1.0f, 2.2f, -2.0f}, {0.0f, 1.0f, 0.0f}, 0.0f, 0.2f, 1.0f),  // a ball
        segment({-2.0f, -0.5f, 3.0f}, {0.2f, 0.1f, -1.0f}, 3.0f, 0.08f, 1.4f),  // towards the camera's view
    };
    // A wall at z = -1 over the right third of the image: rays there stop inside fields.
    std::vector<float> depth(size_t(W) * H, 1.0f);
    for (int y = 0; y < H; ++y)
        for (int x = 2 * W / 3; x < W; ++x) {
            glm::dvec3 q = ray_direction(cam, x, y, W, H);
            double s = (-1.0 - cam.eye.z) / q.z;
            depth[size_t(y) * W + x] = window_depth(cam, glm::vec3(glm::dvec3(cam.eye) + s * q));
        }
    probe.set_depth(depth);
    probe.draw_energy(pass, cam, segs);
    const std::vector<glm::vec4> out = probe.read();

    double peak = 0.0;
    for (const glm::vec4& p : out) peak = std::max(peak, double(p.x));
    ASSERT_GT(peak, 0.1);
    int compared = 0, covered = 0, stopped_by_wall = 0;
    double worst = 0.0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const glm::vec4 p = out[size_t(y) * W + x];
            ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y)) << x << "," << y;
            const glm::dvec3 q = ray_direction(cam, x, y, W, H);
            const double s_end = p.y;
            const double ref = sim::energy_along_ray(segs, glm::dvec3(cam.eye), q, s_end);
            if (ref > 0.0) ++covered;
            if (ref < 1e-3 * peak || sim::energy_singular_distance(segs, glm::dvec3(cam.eye), q, s_end) < 0.1) continue;
            ++compared;
            if (x >= 2 * W / 3 && s_end < 20.0) ++stopped_by_wall;
            const double rel = std::fabs(double(p.x) - ref) / ref;
            worst = std::max(worst, rel);
            EXPECT_LT(rel, 1e-3) << "pixel " << x << "," << y << ": shader " << p.x << ", quadrature " << ref;
        }
    EXPECT_GT(compared, covered / 2);  // most of the field's pixels are away from the singular points
    EXPECT_GT(stopped_by_wall, 50);
    // Per-tile culling gives pixels fewer segments to integrate and changes none.
    const size_t culled_pairs = pass.tiles().pairs();
    pass.method().tile_culling = false;
    probe.draw_energy(pass, cam, segs);
    EXPECT_LT(culled_pairs, pass.tiles().pairs());
    const std::vector<glm::vec4> unculled = probe.read();
    for (size_t i = 0; i < out.size(); ++i)
        ASSERT_EQ(unculled[i].x, out[i].x) << "pixel " << i % W << "," << i / W;
    pass.method().tile_culling = true;
    std::printf("energy exactness: %d rays compared of %d covered, worst relative error %.3g\n", compared, covered,
                worst);
}

TEST_F(EnergyRenderTest, NoNanOrInfForAnyRay) {
    constexpr int N = 33;  // odd: the centre pixel's ray is the view direction
    effects::EnergyProbe probe(N, N);
    struct Case {
        const char* name;
        glm::vec3 eye, target;
        std::vector<EnergySegment> segs;
    };
    const glm::vec3 z(0.0f, 0.0f, -1.0f);
    std::vector<Case> cases = {
        {"along the axis, through M", {0, 0, 0}, {0, 0, -10}, {segment({0, 0, -5}, z, 6.0f, 0.12f, 1.6f)}},
        {"eye at M", {0, 0, -5}, {0, 0, -10}, {segment({0, 0, -5}, z, 6.0f, 0.12f, 1.6f)}},
        {"eye at the head", {0, 0, -11}, {0, 0, -20}, {segment({0, 0, -5}, z, 6.0f, 0.12f, 1.6f)}},
        {"eye in plane I", {0, 0, 0}, {0, 0, -10}, {segment({0, 0, -5}, {1, 0, 0}, 6.0f, 0.12f, 1.6f)}},
        {"eye on the axis inside the beam", {0, 0, -7}, {3, 1, -9}, {segment({0, 0, -5}, z, 6.0f, 0.12f, 1.6f)}},
        {"parallel to the axis", {0, 0, 0}, {0, 0, -10}, {segment({0.5f, 0, -2}, z, 20.0f, 0.12f, 1.6f)}},
        {"perpendicular through M", {0, 0, 0}, {0, 0, -10}, {segment({0, 0, -5}, {0, 1, 0}, 3.0f, 0.12f, 1.6f)}},
        {"zero length and zero strength", {0, 0, 0}, {0, 0, -10},
         {segment({0, 0, -5}, z, 0.0f, 0.12f, 1.6f), segment({0, 0, -3}, z, 4.0f, 0.0f, 1.6f)}},
    };
    // And random eyes around a chain, looking at random points near it.
    sim::Rng rng(2009);
    const std::vector<EnergySegment> chain = {segment({-3, 0, -6}, {1, 0.2f, 0}, 2.0f, 0.12f, 1.6f),
                                              segment({-1, 0.4f, -6}, {1, -0.1f, 0.3f}, 2.0f, 0.12f, 1.6f),
                                              segment({1, 0.2f, -5.4f}, {1, 0, 0}, 2.0f, 0.12f, 1.6f)};
    for (int i = 0; i < 12; ++i) {
        glm::vec3 eye(rng.range(-4.0f, 4.0f), rng.range(-1.5f, 1.5f), rng.range(-8.0f, -2.0f));
        glm::vec3 target(rng.range(-3.0f, 3.0f), rng.range(-0.5f, 0.5f), -6.0f);
        cases.push_back({"random eye near a chain", eye, target + glm::vec3(0.0f, 0.0f, 0.01f), chain});
    }
    for (const Case& c : cases) {
        effects::Camera cam = look(c.eye, c.target, N, N);
        probe.draw_energy(pass, cam, c.segs);
        const std::vector<glm::vec4> out = probe.read();
        int lit = 0;
        for (const glm::vec4& p : out) {
            ASSERT_TRUE(std::isfinite(p.x)) << c.name;
            ASSERT_GE(p.x, 0.0f) << c.name;
            lit += p.x > 0.0f;
        }
        EXPECT_GT(lit, 0) << c.name;
    }
    // The nearly parallel rays are not singular (0.5 m from the axis): they must be exact too.
    effects::Camera cam = look({0, 0, 0}, {0, 0, -10}, N, N);
    probe.draw_energy(pass, cam, cases[5].segs);
    const glm::vec4 centre = probe.read()[size_t(N / 2) * N + N / 2];
    const double ref = sim::energy_along_ray(cases[5].segs, glm::dvec3(0.0), ray_direction(cam, N / 2, N / 2, N, N),
                                             centre.y);
    EXPECT_NEAR(centre.x / ref, 1.0, 1e-3);
}

// Rays from 1e-6 to 1e-2 rad off the degenerate ones: along the axis through M, across
// it through M, parallel to it, and along it from inside the beam. Every one is finite
// in the closed form, the glow and ray marching, and the closed form matches the
// quadrature, the rays through the clamped core around the axis included (the
// quadrature integrates the same clamped density).
TEST_F(EnergyRenderTest, NearDegenerateRaysStayFiniteAndExact) {
    effects::EnergyProbe probe(1, 1);  // the one pixel's ray is the view direction
    const glm::dvec3 z(0, 0, -1), x(-1, 0, 0);
    struct Family {
        const char* name;
        EnergySegment seg;
        glm::dvec3 axis, side_a, side_b;  // the degenerate direction and two normals to tilt it by
    };
    const std::vector<Family> families = {
        {"along the axis through M", segment({0, 0, -5}, {0, 0, -1}, 6.0f, 0.12f, 1.6f), z, {1, 0, 0}, {0, 1, 0}},
        {"across the axis through M", segment({-3, 0, 0}, {0, 0, -1}, 6.0f, 0.12f, 1.6f), x, {0, 0, 1}, {0, 1, 0}},
        {"parallel to the axis", segment({0.5f, 0, -2}, {0, 0, -1}, 6.0f, 0.12f, 1.6f), z, {1, 0, 0}, {0, 1, 0}},
        {"along the axis inside the beam", segment({0, 0, 2}, {0, 0, -1}, 6.0f, 0.12f, 1.6f), z, {1, 0, 0}, {0, 1, 0}},
    };
    const std::vector<glm::vec4> black(1, glm::vec4(0.0f));
    int near_core = 0, rays = 0;
    double worst = 0.0;
    for (const Family& f : families)
        for (int k = 0; k <= 8; ++k) {
            const double angle = 1e-6 * std::pow(10.0, 0.5 * k);
            for (double azimuth : {0.0, 2.0, 4.0}) {
                SCOPED_TRACE(std::string(f.name) + ", " + std::to_string(angle) + " rad, azimuth " +
                             std::to_string(azimuth));
                const glm::dvec3 tilt = std::cos(azimuth) * f.side_a + std::sin(azimuth) * f.side_b;
                const glm::dvec3 dir = std::cos(angle) * f.axis + std::sin(angle) * tilt;
                // Eye at the origin, target one metre away: the direction survives rounding to float.
                const effects::Camera cam = look({0, 0, 0}, glm::vec3(dir), 1, 1);
                const std::vector<EnergySegment> segs = {f.seg};
                ++rays;
                pass.method().march_samples = 120;
                probe.draw_energy(pass, cam, segs);
                const glm::vec4 marched = probe.read()[0];
                ASSERT_TRUE(std::isfinite(marched.x) && marched.x > 0.0f) << "ray marching: " << marched.x;
                pass.method().march_samples = 0;
                probe.draw_glow(pass, cam, segs, black);
                const glm::vec4 glow = probe.read()[0];
                for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(glow[c]) && glow[c] > 0.0f) << "glow: " << glow[c];
                probe.draw_energy(pass, cam, segs);
                const glm::vec4 h = probe.read()[0];
                ASSERT_TRUE(std::isfinite(h.x) && h.x > 0.0f) << "closed form: " << h.x;
                const glm::dvec3 q = ray_direction(cam, 0, 0, 1, 1);
                if (sim::energy_singular_distance(segs, glm::dvec3(0.0), q, h.y) < 2.0 * sim::kEnergyCore_m) ++near_core;
                const double ref = sim::energy_along_ray(segs, glm::dvec3(0.0), q, h.y);
                const double rel = std::fabs(double(h.x) - ref) / ref;
                worst = std::max(worst, rel);
                EXPECT_LT(rel, 1e-3) << "shader " << h.x << ", quadrature " << ref;
            }
        }
    EXPECT_GE(near_core, 70);  // most rays pass within two core radii of M or the axis
    std::printf("near-degenerate rays: %d swept, %d of them within %.2f m of the axis, worst relative error %.3g\n",
                rays, near_core, 2.0 * sim::kEnergyCore_m, worst);
}

// The seed's figures 4.8-4.13: one camera, a wall over the right half of the view
// (z = -20 where x > 0), and the beam moved through every ordering.
struct Ordering {
    const char* name;
    std::vector<EnergySegment> segs;
};

std::vector<EnergySegment> beam_across(float z) {
    return {segment({-6, 0, z}, {1, 0.1f, 0}, 4.0f, 0.12f, 1.6f), segment({-2, 0.4f, z}, {1, -0.1f, 0}, 4.0f, 0.12f, 1.6f),
            segment({2, 0, z}, {1, 0, 0}, 4.0f, 0.12f, 1.6f)};
}

std::vector<Ordering> orderings() {
    return {
        {"1_camera_beam_wall", beam_across(-10.0f)},
        {"2_beam_through_wall", beam_across(-20.0f)},
        {"3_camera_wall_beam", beam_across(-30.0f)},
        // From behind the camera, on through the wall (z = -20) just right of the centre.
        {"4_camera_inside_beam", {segment({0.3f, -0.2f, 4}, {0, 0, -1}, 30.0f, 0.12f, 1.6f)}},
        {"5_beam_behind_camera", beam_across(10.0f)},
        // From beside and behind the camera, across the view (x = 0 at z = -9), into the wall.
        {"6_beam_through_camera_plane", {segment({-3, -0.5f, 6}, {0.2f, 0, -1}, 36.0f, 0.12f, 1.6f)}},
    };
}

TEST_F(EnergyRenderTest, SixOrderingsOfCameraBeamAndGeometry) {
    constexpr int W = 192, H = 112;
    effects::EnergyProbe probe(W, H);
    const effects::Camera cam = look({0, 0, 0}, {0, 0, -1}, W, H);
    std::vector<float> depth(size_t(W) * H, 1.0f);
    std::vector<glm::vec4> background(size_t(W) * H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            glm::dvec3 q = ray_direction(cam, x, y, W, H);
            glm::dvec3 hit = glm::dvec3(cam.eye) + (-20.0 / q.z) * q;
            bool wall = hit.x > 0.0;
            if (wall) depth[size_t(y) * W + x] = window_depth(cam, glm::vec3(hit));
            // Wall: grey with a brick-ish stripe so the cut reads; sky: dark blue.
            float stripe = std::fmod(float(hit.y) + 100.0f, 1.0f) < 0.08f ? 0.6f : 1.0f;
            background[size_t(y) * W + x] = wall ? glm::vec4(0.16f * stripe, 0.15f * stripe, 0.14f * stripe, 1.0f)
                                                 : glm::vec4(0.02f, 0.03f, 0.06f, 1.0f);
        }
    const char* update = std::getenv("SPINDRIFT_UPDATE_GOLDENS");
    const char* png_dir = std::getenv("SPINDRIFT_ENERGY_PNG_DIR");
    const std::filesystem::path golden_dir = std::filesystem::path(SPINDRIFT_TEST_DATA) / "energy";

    const std::vector<float> open_sky(size_t(W) * H, 1.0f);
    for (const Ordering& o : orderings()) {
        SCOPED_TRACE(o.name);
        // H with and without the wall, summed over each half of the view.
        probe.set_depth(open_sky);
        probe.draw_energy(pass, cam, o.segs);
        const std::vector<glm::vec4> free = probe.read();
        probe.set_depth(depth);
        probe.draw_energy(pass, cam, o.segs);
        const std::vector<glm::vec4> energy = probe.read();
        double left = 0.0, right = 0.0, right_free = 0.0, least = 1e30, worst_unhidden = 0.0, worst_left = 0.0;
        double most_hidden = 0.0;  // the largest fraction of a ray's H that the wall takes away
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const float e = energy[size_t(y) * W + x].x, f = free[size_t(y) * W + x].x;
                ASSERT_TRUE(std::isfinite(e));
                (x < W / 2 ? left : right) += e;
                if (x >= W / 2) right_free += f;
                least = std::min(least, double(e));
                const double change = double(std::fabs(e - f)) / std::max(double(f), 1e-3);
                worst_unhidden = std::max(worst_unhidden, change);
                if (x < W / 2) worst_left = std::max(worst_left, change);  // no wall on the left half
                if (f > 1e-3f) most_hidden = std::max(most_hidden, double(f - e) / double(f));
                ASSERT_LE(e, f * (1.0f + 1e-5f) + 1e-6f) << x << "," << y;  // a wall only takes away
            }
        const std::string name = o.name;
        if (name == "1_camera_beam_wall") {
            EXPECT_GT(right, 1.0);
            EXPECT_LT(worst_unhidden, 1e-5);  // nothing hidden: the wall is behind the whole field
        } else if (name == "2_beam_through_wall") {
            EXPECT_GT(right, 0.05 * right_free);  // the part in front of the wall shows
            EXPECT_LT(right, 0.8 * right_free);   // the part behind it does not
        } else if (name == "3_camera_wall_beam") {
            EXPECT_GT(left, 1.0);
            EXPECT_GT(right_free, 1.0);
            EXPECT_EQ(right, 0.0);  // wholly behind the wall
        } else if (name == "4_camera_inside_beam") {
            EXPECT_GT(least, 0.0);  // every ray starts inside the field
            EXPECT_GT(left, 1.0);
            // The rays along the beam lose its last 6 m behind the wall; the rest are untouched.
            EXPECT_LT(right, right_free);
            EXPECT_GT(most_hidden, 0.25);
            EXPECT_GT(right, 0.9 * right_free);
            EXPECT_LT(worst_left, 1e-5);
        } else if (name == "5_beam_behind_camera") {
            EXPECT_EQ(left + right, 0.0);
        } else if (name == "6_beam_through_camera_plane") {
            EXPECT_GT(left, 1.0);
            EXPECT_LT(right, 0.9 * right_free);  // the part past z = -20 is behind the wall
            EXPECT_GT(most_hidden, 0.5);
            EXPECT_GT(right, 0.5 * right_free);  // the part from x = 0 to the wall shows
            EXPECT_LT(worst_left, 1e-5);
        }
        std::printf("ordering %s: H left %.2f, right %.2f of %.2f without the wall, most hidden %.3f\n", o.name, left,
                    right, right_free, most_hidden);

        // The frame: the glow over the background, tone mapped as x / (1 + x) in sRGB-ish gamma.
        probe.draw_glow(pass, cam, o.segs, background);
        const std::vector<glm::vec4> hdr = probe.read();
        game::ImageRGBA8 frame{W, H, std::vector<uint8_t>(size_t(W) * H * 4)};
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const glm::vec4 c = hdr[size_t(H - 1 - y) * W + x];  // top-down
                for (int k = 0; k < 3; ++k)
                    frame.pixels[(size_t(y) * W + x) * 4 + k] =
                        uint8_t(std::lround(255.0 * std::pow(c[k] / (1.0 + c[k]), 1.0 / 2.2)));
                frame.pixels[(size_t(y) * W + x) * 4 + 3] = 255;
            }
        if (name != "5_beam_behind_camera") {
            EXPECT_GT(game::image_stats(frame).luma_stddev, 0.05);
        }
        if (png_dir) game::write_png(std::filesystem::path(png_dir) / (name + ".png"), frame);
        const std::filesystem::path golden = golden_dir / ("ordering_" + name + ".png");
        if (update && std::string(update) == "1") game::write_png(golden, frame);
        const game::CompareResult r = game::compare_frames(frame, game::read_png(golden));
        EXPECT_TRUE(r.passed) << golden << ": " << r.summary;
    }
}

// How much a shot's light brightens a frame: the most in the middle of the image (under
// the beam) and the most at its four corners (far from it), as ratios of luminance.
struct LineLightGain {
    float near, far;
};
LineLightGain line_light_gain(const game::ImageRGBA32F& dark, const game::ImageRGBA32F& lit) {
    const int W = lit.width, H = lit.height;
    auto luma = [&](const game::ImageRGBA32F& img, int x, int y) {
        const float* p = &img.pixels[(size_t(y) * size_t(W) + size_t(x)) * 4];
        return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
    };
    LineLightGain g{0.0f, 0.0f};
    for (int y = H / 2 - 5; y < H / 2 + 5; ++y)
        for (int x = W / 2 - 5; x < W / 2 + 5; ++x) g.near = std::max(g.near, luma(lit, x, y) / luma(dark, x, y));
    for (int y : {2, H - 3})
        for (int x : {2, W - 3}) g.far = std::max(g.far, luma(lit, x, y) / luma(dark, x, y));
    return g;
}

// The beams as line lights: a shot in the world becomes one line light of the frame's
// data, and the lit opaque scene (the ground under it) brightens near the beam and
// nowhere far from it.
TEST_F(EnergyRenderTest, ShotLightsTheGroundAroundIt) {
    constexpr int W = 160, H = 100;
    RenderStage stage(make_test_level(),
                      {.width = W, .height = H, .passes = kLitScene, .shadow_map_size = 512});
    effects::SkyState dusk = stage.sky();
    dusk.sun_radiance = glm::vec3(0.3f);  // the beam's light shows
    stage.set_sky(dusk);
    sim::World& world = stage.world();
    sim::CameraView view;
    view.eye = {-20.0f, 14.0f, -30.0f};
    view.target = {-20.0f, 1.0f, -14.0f};
    const effects::Camera cam = stage.camera(view);
    auto render = [&]() {
        stage.draw(cam);
        return stage.hdr();
    };
    const game::ImageRGBA32F dark = render();
    // A grown shot 2 m over the land, across the view.
    sim::Weapon& weapon = world.get<sim::Weapon>();
    weapon.fire({-28.0f, 3.0f, -14.0f}, {1.0f, 0.0f, 0.0f});
    for (int t = 0; t < 12; ++t) world.step({});
    ASSERT_EQ(weapon.shots().size(), 1u);
    const game::ImageRGBA32F lit = render();
    ASSERT_EQ(stage.renderer().frame_data().line_lights.size(), 1u);

    // Under the beam (the middle of the image) against the corners, far from it.
    const auto [near_gain, far_gain] = line_light_gain(dark, lit);
    EXPECT_GT(near_gain, 1.5f);
    EXPECT_LT(far_gain, 1.001f);
    std::printf("line light: ground under the beam x%.2f, far corners x%.4f\n", near_gain, far_gain);
}

// The same over the sea: the water's shading takes the line lights too, so the sea
// under a shot brightens and the sea far from it does not.
TEST_F(EnergyRenderTest, ShotLightsTheWaterUnderIt) {
    constexpr int W = 160, H = 100;
    // No wave grid in the world: the water pass draws a flat sea at 0.
    RenderStage stage(make_test_level(), {.width = W,
                                          .height = H,
                                          .passes = kLitScene | kSceneCopyPass | kWaterPass,
                                          .shadow_map_size = 512});
    effects::SkyState dusk = stage.sky();
    dusk.sun_radiance = glm::vec3(0.3f);  // the beam's light shows
    stage.set_sky(dusk);
    sim::World& world = stage.world();
    sim::CameraView view;
    view.eye = {60.0f, 14.0f, 30.0f};
    view.target = {60.0f, 0.0f, 46.0f};
    const effects::Camera cam = stage.camera(view);
    auto render = [&]() {
        stage.draw(cam);
        return stage.hdr();
    };
    const game::ImageRGBA32F dark = render();
    // A shot 2 m over the sea, across the view.
    world.get<sim::Weapon>().fire({52.0f, 2.0f, 46.0f}, {1.0f, 0.0f, 0.0f});
    for (int t = 0; t < 12; ++t) world.step({});
    ASSERT_EQ(world.get<sim::Weapon>().shots().size(), 1u);
    ASSERT_FALSE(world.get<sim::Weapon>().shots()[0].hit());
    const game::ImageRGBA32F lit = render();
    const auto [near_gain, far_gain] = line_light_gain(dark, lit);
    EXPECT_GT(near_gain, 1.3f);
    EXPECT_LT(far_gain, 1.001f);
    std::printf("line light: sea under the beam x%.2f, far corners x%.4f\n", near_gain, far_gain);
    if (const char* png_dir = std::getenv("SPINDRIFT_ENERGY_PNG_DIR")) {
        for (const auto& [name, img] : {std::pair{"sea_dark.png", &dark}, std::pair{"sea_lit.png", &lit}}) {
            game::ImageRGBA8 out{W, H, std::vector<uint8_t>(size_t(W) * H * 4, 255)};
            for (size_t i = 0; i < size_t(W) * H; ++i)
                for (size_t k = 0; k < 3; ++k) {
                    const double c = img->pixels[i * 4 + k];
                    out.pixels[i * 4 + k] = uint8_t(std::lround(255.0 * std::pow(c / (1.0 + c), 1.0 / 2.2)));
                }
            game::write_png(std::filesystem::path(png_dir) / name, out);
        }
    }
}

// The pass in the frame: the glow lands in the scene colour where the beam is, and the
// bloom spreads some of it beyond the field's reach, only near the beam.
TEST_F(EnergyRenderTest, GlowAndBloomLandInTheSceneAroundTheBeam) {
    constexpr int W = 160, H = 96;
    // The energy pass alone over cleared targets, drawing the test's beam.
    RenderStage stage(make_test_level(), {.width = W, .height = H, .passes = kEnergyPass, .shadow_map_size = 512});
    const GLuint scene = stage.targets().hdr().id();
    const effects::Camera cam = look({0, 20, 0}, {0, 20, -1}, W, H);  // level, at the sky
    const std::vector<EnergySegment> beam = {segment({-3, 20, -15}, {1, 0, 0}, 6.0f, 0.12f, 1.1f)};
    effects::EnergyPass& energy = stage.pass<effects::EnergyPass>();
    auto frame_with = [&](float bloom) {
        const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        glClearNamedFramebufferfv(scene, GL_COLOR, 0, zero);
        const float far = 1.0f;
        glClearNamedFramebufferfv(scene, GL_DEPTH, 0, &far);
        energy.look().bloom = bloom;
        stage.draw(cam, {.replaced = kEnergyPass,
                         .replacement = [&](const effects::FrameContext& frame) { energy.draw(frame, beam); }});
        return stage.hdr();
    };
    const game::ImageRGBA32F plain = frame_with(0.0f), bloomed = frame_with(0.5f);
    // Blue: the glow colour's strongest channel.
    auto blue = [&](const game::ImageRGBA32F& img, int x, int y) { return img.pixels[(size_t(y) * W + size_t(x)) * 4 + 2]; };
    // The beam crosses the middle row; the field reaches 1.1 m (about 6 px) above it.
    EXPECT_GT(blue(plain, W / 2, H / 2), 0.5f);
    EXPECT_EQ(blue(plain, W / 2, H / 2 - 12), 0.0f);
    EXPECT_GT(blue(bloomed, W / 2, H / 2 - 12), 0.0f);             // bled beyond the field
    EXPECT_GT(blue(bloomed, W / 2, H / 2), blue(plain, W / 2, H / 2));
    EXPECT_EQ(blue(bloomed, W / 2, 2), 0.0f);                      // and not far away
    for (float v : bloomed.pixels) ASSERT_TRUE(std::isfinite(v));
}

// The bloom bins the segments again at a quarter of the size; its lists must not land
// where the glow's draw, maybe still rasterising, reads its own (llvmpipe did not wait:
// harbour_energy tick 525 showed a tile of the ball without its glow, one run in a few).
TEST_F(EnergyRenderTest, TheBloomLeavesTheGlowsListsAlone) {
    constexpr int W = 160, H = 96;
    RenderStage stage(make_test_level(), {.width = W, .height = H, .passes = kEnergyPass, .shadow_map_size = 512});
    const effects::Camera cam = look({0, 20, 0}, {0, 20, -1}, W, H);
    // Two shots, so the bloom's few tiles list other segments than the glow's first ones.
    const std::vector<EnergySegment> shots = {segment({-3, 20, -15}, {1, 0, 0}, 6.0f, 0.12f, 1.1f),
                                              segment({2, 21, -12}, {0, 1, 0}, 0.0f, 0.12f, 0.8f)};
    effects::EnergyPass& energy = stage.pass<effects::EnergyPass>();
    ASSERT_GT(energy.look().bloom, 0.0f);
    auto frame = [&] {
        stage.draw(cam, {.replaced = kEnergyPass,
                         .replacement = [&](const effects::FrameContext& f) { energy.draw(f, shots); }});
        return stage.hdr();
    };
    const game::ImageRGBA32F first = frame();
    effects::EnergyTileGrid glow, bloom;
    effects::bin_energy_segments(cam, W, H, shots, true, glow);
    effects::bin_energy_segments(cam, W / 4, H / 4, shots, true, bloom);
    ASSERT_FALSE(glow.tiles.empty());
    ASSERT_FALSE(bloom.tiles.empty());
    ASSERT_NE(bloom.tiles.front(), glow.tiles.front());
    // What the glow's draw reads, after the bloom's uploads.
    const effects::EnergyPass::FieldBuffers& buffers = energy.glow_buffers();
    std::vector<glm::uvec4> tiles(glow.tiles.size());
    std::vector<uint32_t> indices(glow.indices.size());
    glGetNamedBufferSubData(buffers.tiles.id(), 0, GLsizeiptr(tiles.size() * sizeof(glm::uvec4)), tiles.data());
    glGetNamedBufferSubData(buffers.tile_segments.id(), 0, GLsizeiptr(indices.size() * sizeof(uint32_t)),
                            indices.data());
    EXPECT_EQ(tiles, glow.tiles);
    EXPECT_EQ(indices, glow.indices);
    // And the same frame again, bit for bit.
    EXPECT_EQ(frame().pixels, first.pixels);
}

// A beam standing half in the harbour: the water pass writes the sea surface into the
// scene depth, so the part under the water is hidden like the part behind a wall.
TEST_F(EnergyRenderTest, WaterHidesTheBeamBelowItsSurface) {
    constexpr int W = 128, H = 96;
    // No wave grid in the world: the water pass draws a flat sea at 0. The scene copy
    // keeps the depth before the water.
    RenderStage stage(make_test_level(), {.width = W,
                                          .height = H,
                                          .passes = kLitScene | kSceneCopyPass | kWaterPass,
                                          .shadow_map_size = 512});
    const effects::Camera cam = look({40.0f, 3.0f, 10.0f}, {40.0f, 0.0f, 30.0f}, W, H);
    stage.draw(cam);
    const std::vector<EnergySegment> beam = {segment({40.0f, -3.0f, 30.0f}, {0, 1, 0}, 6.0f, 0.12f, 1.1f)};

    effects::gl::Texture target = effects::gl::Texture::create_2d("test.energy", GL_RGBA32F, W, H);
    effects::gl::Framebuffer fbo = effects::gl::Framebuffer::create("test.energy");
    fbo.attach_colour(0, target);
    fbo.check_complete();
    auto energy_over = [&](const effects::gl::Texture& depth) {
        fbo.bind();
        glViewport(0, 0, W, H);
        const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, zero);
        pass.draw_field(cam, depth, W, H, beam, true);
        return game::read_framebuffer_rgba32f(fbo.id(), GL_COLOR_ATTACHMENT0, W, H);
    };
    const game::ImageRGBA32F seabed = energy_over(stage.targets().depth_copy());
    const game::ImageRGBA32F surface = energy_over(stage.targets().depth());
    // Rows top-down: the head (y = 3) above the horizon of the view, the foot under water.
    auto column_sum = [&](const game::ImageRGBA32F& img, int y0, int y1) {
        double sum = 0.0;
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < W; ++x) sum += img.pixels[(size_t(y) * W + size_t(x)) * 4];
        return sum;
    };
    const double all_seabed = column_sum(seabed, 0, H), all_surface = column_sum(surface, 0, H);
    EXPECT_GT(all_seabed, 10.0);
    EXPECT_LT(all_surface, 0.8 * all_seabed);  // the part under the water is gone
    EXPECT_GT(all_surface, 0.2 * all_seabed);  // the part above it is not
    // The head, in front of the sky, is the same either way.
    glm::vec4 head = cam.view_proj * glm::vec4(40.0f, 3.0f, 30.0f, 1.0f);
    const int hx = int((head.x / head.w * 0.5f + 0.5f) * W), hy = int((0.5f - head.y / head.w * 0.5f) * H);
    ASSERT_TRUE(hx >= 0 && hx < W && hy >= 0 && hy < H);
    const float a = seabed.pixels[(size_t(hy) * W + size_t(hx)) * 4], b = surface.pixels[(size_t(hy) * W + size_t(hx)) * 4];
    EXPECT_GT(a, 0.0f);
    EXPECT_NEAR(b / a, 1.0f, 1e-4f);
    std::printf("water occlusion: H summed over the view %.1f over the sea bed, %.1f over the sea surface\n",
                all_seabed, all_surface);
    if (const char* png_dir = std::getenv("SPINDRIFT_ENERGY_PNG_DIR")) {
        pass.draw(stage.context(cam), beam);
        const game::ImageRGBA32F hdr = stage.hdr();
        game::ImageRGBA8 image{W, H, std::vector<uint8_t>(size_t(W) * H * 4, 255)};
        for (size_t i = 0; i < size_t(W) * H; ++i)
            for (size_t k = 0; k < 3; ++k) {
                const double c = hdr.pixels[i * 4 + k];
                image.pixels[i * 4 + k] = uint8_t(std::lround(255.0 * std::pow(c / (1.0 + c), 1.0 / 2.2)));
            }
        game::write_png(std::filesystem::path(png_dir) / "beam_in_water.png", image);
    }
}

}  // namespace


// Per-tile culling against each segment's projected capsule: it takes away no pixel's
// energy (segments all over the screen, at its edges and reaching past them, at 1 to
// 60 m, across and along the view), lists a segment on few more tiles than its field
// lights, and on none when it is wholly behind the eye.
TEST_F(EnergyRenderTest, TileCullingFollowsTheProjectedCapsuleAndChangesNoPixel) {
    constexpr int W = 320, H = 192, kTile = effects::EnergyTileGrid::kTilePx;
    effects::EnergyProbe probe(W, H);
    const effects::Camera cam = look({0, 1, 0}, {0, 1, -1}, W, H);
    sim::Rng rng(16);
    std::vector<EnergySegment> segs;
    for (int i = 0; i < 40; ++i) {
        const float depth = rng.range(1.0f, 60.0f);
        const glm::vec3 start(rng.range(-1.1f, 1.1f) * depth, 1.0f + rng.range(-0.65f, 0.65f) * depth, -depth);
        const glm::vec3 dir(rng.range(-1.0f, 1.0f), rng.range(-0.3f, 0.3f), rng.range(-1.0f, 1.0f));
        segs.push_back(segment(start, dir, rng.range(0.0f, 5.0f), 0.12f, rng.range(0.5f, 1.6f)));
    }
    probe.draw_energy(pass, cam, segs);
    const std::vector<glm::vec4> culled = probe.read();
    pass.method().tile_culling = false;
    probe.draw_energy(pass, cam, segs);
    const std::vector<glm::vec4> unculled = probe.read();
    pass.method().tile_culling = true;
    int lit = 0;
    for (size_t i = 0; i < culled.size(); ++i) {
        ASSERT_EQ(culled[i].x, unculled[i].x) << "pixel " << i % W << "," << i / W;
        lit += culled[i].x > 0.0f;
    }
    EXPECT_GT(lit, W * H / 4);

    // One segment at a time: the tiles it is listed on against the tiles its field lights.
    int listed_total = 0, lit_total = 0;
    for (const EnergySegment& s : segs) {
        const std::vector<EnergySegment> one = {s};
        probe.draw_energy(pass, cam, one);
        const std::vector<glm::vec4> h = probe.read();
        std::vector<bool> lit_tile(size_t((W / kTile) * (H / kTile)), false);
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x)
                if (h[size_t(y) * W + x].x > 0.0f) lit_tile[size_t(y / kTile) * (W / kTile) + x / kTile] = true;
        listed_total += int(pass.tiles().tiles.size());
        lit_total += int(std::count(lit_tile.begin(), lit_tile.end(), true));
    }
    EXPECT_GE(listed_total, lit_total);
    EXPECT_LT(listed_total, 2 * lit_total);
    std::printf("tile culling: %d tiles listed for %d lit, one segment at a time\n", listed_total, lit_total);

    const std::vector<EnergySegment> behind = {segment({0, 1, 3}, {1, 0, 0}, 4.0f, 0.12f, 1.6f)};
    probe.draw_energy(pass, cam, behind);
    EXPECT_TRUE(pass.tiles().tiles.empty());
}
