// sim/water's wave grid: the seed's explicit scheme, its free boundary and damping, the
// stability bound, land cells and reflection, in grids built in code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "ErrorMessage.h"
#include "sim/core/Rng.h"
#include "sim/water/WaveGrid.h"
#include "sim/water/WaveRow.h"

namespace {

constexpr float kDt = 1.0f / 60.0f;

// A grid with c = 1/4 (v = 15 m/s at h = 0.5 m): fronts move half a cell per tick.
sim::WaveGridParams fast_grid(int size) {
    sim::WaveGridParams p;
    p.size = size;
    p.spacing_m = 0.5f;
    p.origin_xz = {0.0f, 0.0f};
    p.wave_speed_mps = 15.0f;
    p.damping_per_s = 0.0f;
    return p;
}

std::vector<float> gaussian_bump(int size, float ci, float cj, float sigma_cells, float amplitude) {
    std::vector<float> y(size_t(size) * size_t(size));
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            float dx = float(i) - ci, dz = float(j) - cj;
            y[size_t(j) * size_t(size) + size_t(i)] =
                amplitude * std::exp(-(dx * dx + dz * dz) / (2.0f * sigma_cells * sigma_cells));
        }
    return y;
}

TEST(WaveGrid, GaussianBumpWithoutDampingKeepsItsVolume) {
    sim::WaveGrid g(fast_grid(128), kDt);
    g.set_heights(gaussian_bump(128, 50.0f, 70.0f, 3.0f, 0.2f));
    const double v0 = g.volume();
    ASSERT_GT(v0, 0.5);
    double worst = 0.0;
    for (int t = 0; t < 400; ++t) {  // long enough to reflect off every edge
        g.step();
        worst = std::max(worst, std::fabs(g.volume() - v0) / v0);
    }
    EXPECT_LT(worst, 1e-3);
    // The bump has really spread: the centre is far below its start.
    EXPECT_LT(std::fabs(g.height(50, 70)), 0.05f);
}

// Radius (m) of the largest |height| along the four axis rays from the centre.
float front_radius(const sim::WaveGrid& g, int c) {
    float sum = 0.0f;
    const int dirs[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& d : dirs) {
        int best = 0;
        float peak = -1.0f;
        for (int r = 1; r < c; ++r) {
            float a = std::fabs(g.height(c + d[0] * r, c + d[1] * r));
            if (a > peak) {
                peak = a;
                best = r;
            }
        }
        sum += float(best);
    }
    return sum / 4.0f * g.spacing();
}

TEST(WaveGrid, RingFrontTravelsAtTheWaveSpeed) {
    sim::WaveGrid g(fast_grid(256), kDt);
    g.set_heights(gaussian_bump(256, 128.0f, 128.0f, 3.0f, 0.2f));
    float r1 = 0.0f, r2 = 0.0f;
    for (int t = 1; t <= 200; ++t) {
        g.step();
        if (t == 60) r1 = front_radius(g, 128);
        if (t == 200) r2 = front_radius(g, 128);
    }
    const float speed = (r2 - r1) / (140.0f * kDt);
    EXPECT_NEAR(speed, 15.0f, 1.5f) << "front at " << r1 << " m then " << r2 << " m";
}

TEST(WaveGrid, RefusesUnstableParametersNamingTheBound) {
    sim::WaveGridParams p;
    p.wave_speed_mps = 40.0f;  // c = 40^2 / 60^2 / 0.25 = 1.78
    std::string msg = message_of([&] { sim::WaveGrid g(p, kDt); });
    EXPECT_NE(msg.find("c = v^2 dt^2 / h^2 <= 0.5"), std::string::npos) << msg;
    EXPECT_NE(msg.find("v = 40"), std::string::npos) << msg;
    EXPECT_NE(msg.find("h = 0.5"), std::string::npos) << msg;
    p = {};
    p.wave_speed_mps = 21.2f;  // c = 0.4993: just stable
    EXPECT_NO_THROW(sim::WaveGrid(p, kDt));
    p.wave_speed_mps = 21.3f;  // c = 0.504
    EXPECT_THROW(sim::WaveGrid(p, kDt), std::invalid_argument);
    p = {};
    p.size = 4096;
    EXPECT_NE(message_of([&] { sim::WaveGrid g(p, kDt); }).find("size must be 8..2048"), std::string::npos);
    p = {};
    p.damping_per_s = 1.5f;
    EXPECT_NE(message_of([&] { sim::WaveGrid g(p, kDt); }).find("damping_per_s"), std::string::npos);
    sim::WaveGrid ok({}, kDt);
    EXPECT_THROW(ok.set_land_mask(std::vector<uint8_t>(10)), std::invalid_argument);
    EXPECT_THROW(ok.push({NAN, 3.0f}, 1.0f, 0.1f), std::invalid_argument);
}

TEST(WaveGrid, SampleIsBilinearAndNormalTiltsAgainstTheSlope) {
    sim::WaveGridParams p = fast_grid(16);
    p.origin_xz = {-2.0f, 3.0f};
    sim::WaveGrid g(p, kDt);
    std::vector<float> ramp(16 * 16);
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) ramp[size_t(j) * 16 + size_t(i)] = 0.1f * float(i) * 0.5f;  // 0.1 m per m in x
    g.set_heights(ramp);
    EXPECT_NEAR(g.sample({-2.0f + 1.25f, 3.0f + 2.1f}), 0.125f, 1e-6f);
    EXPECT_EQ(g.sample({-2.5f, 4.0f}), 0.0f);  // outside
    glm::vec3 n = g.normal({1.0f, 5.0f});
    EXPECT_NEAR(n.x, -0.1f / std::sqrt(1.01f), 1e-4f);
    EXPECT_NEAR(n.z, 0.0f, 1e-6f);
    g.push({1.0f, 5.0f}, 1.0f, 0.05f);
    EXPECT_LT(g.sample({1.0f, 5.0f}), 0.3f - 0.04f);     // pushed down there
    EXPECT_NEAR(g.sample({4.0f, 5.0f}), 0.6f, 1e-6f);    // untouched further away
}

TEST(WaveGrid, LandStaysPinnedAndReflectsAndThreadsAgree) {
    sim::WaveGridParams p = fast_grid(64);
    p.damping_per_s = 0.2f;
    sim::WaveGrid a(p, kDt), b(p, kDt);
    std::vector<uint8_t> land(64 * 64, 0);
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 64; ++i) land[size_t(j) * 64 + size_t(i)] = 1;  // a quay along z
    for (int i = 30; i < 34; ++i) land[size_t(40) * 64 + size_t(i)] = 1;    // and a pier head
    a.set_land_mask(land);
    b.set_land_mask(land);
    a.set_heights(gaussian_bump(64, 32.0f, 30.0f, 2.0f, 0.3f));
    b.set_heights(gaussian_bump(64, 32.0f, 30.0f, 2.0f, 0.3f));
    sim::JobPool pool(3);
    for (int t = 0; t < 150; ++t) {
        a.step();
        b.step(pool);
    }
    EXPECT_EQ(a.heights(), b.heights());
    EXPECT_EQ(a.hash(), b.hash());
    for (size_t k = 0; k < land.size(); ++k)
        if (land[k]) {
            ASSERT_EQ(a.heights()[k], 0.0f) << "land cell " << k;
        }
    double moving = 0.0;
    for (int i = 0; i < 64; ++i) moving += std::fabs(a.height(i, 21));
    EXPECT_GT(moving, 1e-3);  // waves reached the quay
    b.step();
    EXPECT_NE(a.hash(), b.hash());
}

double rms(const std::vector<float>& y) {
    double s = 0.0;
    for (float v : y) s += double(v) * v;
    return std::sqrt(s / double(y.size()));
}

TEST(WaveGrid, DampingTakesTheStatedFractionOfWaveEnergyPerSecond) {
    // damping_per_s is the fraction of wave energy lost per second, so heights shrink
    // by sqrt(1 - d) each second against the same waves without damping.
    sim::WaveGridParams free_p = fast_grid(128), damped_p = fast_grid(128);
    damped_p.damping_per_s = 0.25f;
    sim::WaveGrid free_g(free_p, kDt), damped(damped_p, kDt);
    free_g.set_heights(gaussian_bump(128, 64.0f, 64.0f, 3.0f, 0.2f));
    damped.set_heights(gaussian_bump(128, 64.0f, 64.0f, 3.0f, 0.2f));
    for (int second = 1; second <= 4; ++second) {
        for (int t = 0; t < 60; ++t) {
            free_g.step();
            damped.step();
        }
        const double ratio = rms(damped.heights()) / rms(free_g.heights());
        EXPECT_NEAR(ratio, std::pow(0.75, 0.5 * second), 0.01) << "after " << second << " s";
    }
}

TEST(WaveGrid, QuayReflectsTheFrontBack) {
    // The same bump 15 m off a quay and on open water: only by the quay does a front
    // come back to the bump's seaward side, with the sign and size of the direct one
    // at the same travel distance (the seed's free boundary reflects like a mirror).
    sim::WaveGrid quay(fast_grid(128), kDt), open(fast_grid(128), kDt);
    std::vector<uint8_t> land(128 * 128, 0);
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 128; ++i) land[size_t(j) * 128 + size_t(i)] = 1;
    quay.set_land_mask(land);
    quay.set_heights(gaussian_bump(128, 64.0f, 50.0f, 2.0f, 0.3f));
    open.set_heights(gaussian_bump(128, 64.0f, 50.0f, 2.0f, 0.3f));
    // Fronts move half a cell per tick: the quay (30 cells away) is reached at tick 60;
    // the echo passes (64, 40), 50 cells of travel, near tick 100.
    float echo = 0.0f, open_there = 0.0f, direct = 0.0f;
    int echo_tick = -1;
    for (int t = 1; t <= 130; ++t) {
        quay.step();
        open.step();
        if (t < 80) continue;
        if (std::fabs(quay.height(64, 40)) > std::fabs(echo)) {
            echo = quay.height(64, 40);
            echo_tick = t;
        }
        open_there = std::max(open_there, std::fabs(open.height(64, 40)));
        if (std::fabs(open.height(64, 100)) > std::fabs(direct)) direct = open.height(64, 100);  // 50 cells out
    }
    EXPECT_GT(echo, 0.0f);
    EXPECT_NEAR(echo_tick, 100, 6);
    EXPECT_GT(std::fabs(echo), 5.0f * open_there) << "open water " << open_there;
    EXPECT_NEAR(echo / direct, 1.0f, 0.3f) << "echo " << echo << ", direct " << direct;
}

TEST(WaveGrid, TheAvx2RowGivesTheBaselineBits) {
    // Replays made on one processor must replay on another: the AVX2 code of the tight
    // loop and the baseline one must agree to the bit, heights near the flush level and
    // rows of every length the vector loop splits differently included.
    if (!sim::wave_row_has_avx2()) GTEST_SKIP() << "no AVX2 here";
    sim::Rng rng(11, 3);
    const sim::WaveRowWeights w{0.24f, 1.0f + 0.999f - 0.72f, 1.0f + 0.999f - 0.96f, 0.999f};
    for (size_t n : {2u, 3u, 7u, 8u, 9u, 17u, 31u, 64u, 255u, 512u}) {
        std::vector<float> up(n), row(n), down(n), out_a(n), out_b(n);
        for (size_t i = 0; i < n; ++i) {
            const float scale = i % 5 == 0 ? 1e-29f : (i % 7 == 0 ? 1e-31f : 0.3f);
            up[i] = scale * rng.range(-1.0f, 1.0f);
            row[i] = scale * rng.range(-1.0f, 1.0f);
            down[i] = scale * rng.range(-1.0f, 1.0f);
            out_a[i] = out_b[i] = scale * rng.range(-1.0f, 1.0f);
        }
        sim::step_wave_row(up.data(), row.data(), down.data(), out_a.data(), n, w, sim::WaveRowCode::kBaseline);
        sim::step_wave_row(up.data(), row.data(), down.data(), out_b.data(), n, w, sim::WaveRowCode::kAvx2);
        EXPECT_EQ(std::memcmp(out_a.data(), out_b.data(), n * sizeof(float)), 0) << "row of " << n;
    }
}

}  // namespace
