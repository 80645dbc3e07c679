// The water pass on a real headless context: the flat sea, the wave grid (at rest it
// must match the flat sea; a bump must show), splash sheets, spray, bad input, and a
// world whose WaterSim was hit by a thrown stone. Set SPINDRIFT_WATER_PNG_DIR to
// write the frames as PNGs.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "SimTestLevel.h"
#include "effects/water/SplashSheetMesh.h"
#include "effects/water/SurfaceLod.h"
#include "effects/water/WaterPass.h"
#include "effects/water/WaterSurfaceMesh.h"
#include "game/capture/ImageFiles.h"
#include "sim/objects/ThrownObjects.h"
#include "sim/water/WaterSim.h"
#include "sim/water/WaveGrid.h"

using effects::WaterView;
using effects::WaveHeights;

namespace {

constexpr int kWidth = 320, kHeight = 200;

// The lit scene, the water and the tonemap.
const StagePasses kWaterFrame = kLitScene | kSceneCopyPass | kWaterPass | kTonemapPass;

// Looking south over the quay at the harbour water.
sim::CameraView harbour_view() {
    sim::CameraView v;
    v.eye = {7.0f, 6.0f, -1.0f};
    v.target = {10.0f, 0.0f, 11.0f};
    v.fov_y_deg = 60.0f;
    return v;
}

// A grid over the harbour in front of the camera, at rest until a test moves it.
struct TestGrid {
    int size = 128;
    float spacing = 0.25f;
    glm::vec2 origin{-6.0f, 2.0f};
    std::vector<float> heights = std::vector<float>(size_t(128 * 128), 0.0f);
    WaveHeights view() const { return {size, spacing, origin, heights}; }
};

float luminance(const game::ImageRGBA8& img, int x, int y) {
    const uint8_t* p = &img.pixels[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
    return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

// Variance over a window of the luminance difference between two images: how much
// one departs from the other, ignoring gradients they share (sky, distance haze).
float window_difference_variance(const game::ImageRGBA8& a, const game::ImageRGBA8& b, glm::ivec2 c, int half) {
    double sum = 0, sum2 = 0;
    int n = 0;
    for (int y = std::max(c.y - half, 0); y <= std::min(c.y + half, a.height - 1); ++y)
        for (int x = std::max(c.x - half, 0); x <= std::min(c.x + half, a.width - 1); ++x) {
            double d = luminance(a, x, y) - luminance(b, x, y);
            sum += d;
            sum2 += d * d;
            ++n;
        }
    double mean = sum / n;
    return float(sum2 / n - mean * mean);
}

// Largest channel difference at each pixel, and how many pixels differ by more than tol.
int pixels_differing(const game::ImageRGBA8& a, const game::ImageRGBA8& b, int tol, glm::ivec2 lo = {0, 0},
                     glm::ivec2 hi = {kWidth, kHeight}) {
    int n = 0;
    for (int y = std::max(lo.y, 0); y < std::min(hi.y, kHeight); ++y)
        for (int x = std::max(lo.x, 0); x < std::min(hi.x, kWidth); ++x) {
            size_t o = (size_t(y) * kWidth + size_t(x)) * 4;
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(a.pixels[o + c]) - int(b.pixels[o + c])) > tol) {
                    ++n;
                    break;
                }
        }
    return n;
}

size_t non_finite_values(const game::ImageRGBA32F& img) {
    size_t n = 0;
    for (float v : img.pixels) n += std::isfinite(v) ? 0 : 1;
    return n;
}

void maybe_write_png(const std::string& name, const game::ImageRGBA8& img) {
    if (const char* dir = std::getenv("SPINDRIFT_WATER_PNG_DIR"))
        game::write_png(std::filesystem::path(dir) / (name + ".png"), img);
}

}  // namespace

class WaterRenderTest : public HeadlessTest {
protected:
    void SetUp() override {
        HeadlessTest::SetUp();
        use_world(std::make_unique<sim::World>(make_test_level()));
    }
    // The test level's world, or one of the test's own.
    void use_world(std::unique_ptr<sim::World> world) {
        stage_ = std::make_unique<RenderStage>(game::GameSession{game::LoadedLevel{}, std::move(world)},
                                               StageOptions{.width = kWidth, .height = kHeight, .passes = kWaterFrame});
        // Wind ripples would add detail everywhere that the comparisons below must
        // see through; they are tested on their own.
        water_pass().look().ripples = 0.0f;
    }
    void TearDown() override { stage_.reset(); }

    // Renders one frame; with a view the water pass draws it, else it reads the world.
    void render(const WaterView* view, double time_s = 0.0) {
        if (!view) {
            stage_->draw(camera_, {.time_s = time_s});
            return;
        }
        auto draw_view = [&](const effects::FrameContext& frame) { water_pass().draw(frame, *view); };
        stage_->draw(camera_, {.time_s = time_s, .replaced = kWaterPass, .replacement = draw_view});
    }
    effects::WaterPass& water_pass() { return stage_->pass<effects::WaterPass>(); }

    // World position of image pixel (x, y) (rows top-down) from the depth buffer.
    glm::vec3 world_at(const std::vector<float>& depth, int x, int y) const {
        float d = depth[size_t(y) * kWidth + size_t(x)];
        glm::vec4 ndc((float(x) + 0.5f) / kWidth * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / kHeight * 2.0f,
                      d * 2.0f - 1.0f, 1.0f);
        glm::vec4 p = camera_.inv_view_proj * ndc;
        return glm::vec3(p) / p.w;
    }
    // Image pixel (rows top-down) where a world point lands.
    glm::ivec2 pixel_of(glm::vec3 p) const {
        glm::vec4 c = camera_.view_proj * glm::vec4(p, 1.0f);
        glm::vec2 ndc = glm::vec2(c) / c.w;
        return {int((ndc.x * 0.5f + 0.5f) * kWidth), int((0.5f - ndc.y * 0.5f) * kHeight)};
    }

    std::unique_ptr<RenderStage> stage_;
    effects::Camera camera_ = effects::make_camera(harbour_view(), float(kWidth) / float(kHeight));
};

double area_xz(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    return 0.5 * (double(b.x - a.x) * double(c.y - a.y) - double(b.y - a.y) * double(c.x - a.x));
}

TEST(WaterSurfaceMesh, TilesAtEveryStrideAndTheFrameCoverTheSquareOnce) {
    std::vector<float> heights(size_t(40 * 40), 0.0f);
    WaveHeights grid{40, 0.5f, {-5.0f, 3.0f}, heights};
    effects::WaterSurfaceMesh m = effects::make_water_surface_mesh(&grid, 256, 16, 100.0f);
    const effects::LatticeLayout& l = m.lattice;
    ASSERT_EQ(l.lattice_cells, 64) << "39 cells round up to 64";
    ASSERT_EQ(l.tile_cells, 16);
    ASSERT_EQ(l.tiles_per_side, 4);
    EXPECT_FLOAT_EQ(l.cell_m, 19.5f / 64.0f);
    ASSERT_EQ(m.tile_strides.size(), 5u);  // strides 1, 2, 4, 8, 16
    const double lattice_area = 19.5 * 19.5;
    for (size_t k = 0; k < m.tile_strides.size(); ++k) {
        const effects::IndexRange& r = m.tile_strides[k];
        const int per_side = 16 >> k;
        EXPECT_EQ(r.count, uint32_t(per_side * per_side * 6));
        double area = 0.0;
        for (int ty = 0; ty < 4; ++ty)
            for (int tx = 0; tx < 4; ++tx)
                for (uint32_t q = r.first; q < r.first + r.count; q += 3) {
                    glm::vec2 o = glm::vec2(tx, ty) * 16.0f, p[3];
                    for (int c = 0; c < 3; ++c) p[c] = effects::lattice_xz(l, o + m.vertices[m.indices[q + c]].coord);
                    double s = area_xz(p[0], p[1], p[2]);
                    ASSERT_GT(s, 0.0) << "stride " << (1 << k) << ": triangle not counter-clockwise";
                    area += s;
                }
        EXPECT_NEAR(area, lattice_area, 1e-4 * lattice_area) << "stride " << (1 << k);
    }
    double frame_area = 0.0;
    for (uint32_t q = m.frame.first; q < m.frame.first + m.frame.count; q += 3) {
        glm::vec2 p[3];
        for (int c = 0; c < 3; ++c) {
            const effects::SurfaceVertex& v = m.vertices[m.indices[q + c]];
            p[c] = v.explicit_xz > 0.0f ? v.coord : effects::lattice_xz(l, v.coord);
        }
        double s = area_xz(p[0], p[1], p[2]);
        ASSERT_GT(s, 0.0) << "frame triangle not counter-clockwise";
        frame_area += s;
    }
    // All counter-clockwise and adding up to the square: no gaps, no overlaps.
    EXPECT_NEAR(frame_area + lattice_area, 200.0 * 200.0, 1e-4 * 200.0 * 200.0);

    effects::WaterSurfaceMesh flat = effects::make_water_surface_mesh(nullptr, 256, 16, 100.0f);
    EXPECT_EQ(flat.lattice.lattice_cells, 0);
    EXPECT_EQ(flat.frame.count, 6u);
    EXPECT_THROW(effects::make_water_surface_mesh(&grid, 256, 12, 100.0f), std::invalid_argument);
}

TEST(SurfaceLod, StridesGrowWithDistanceAndSharedEdgesAgree) {
    effects::LatticeLayout l{256, 32, 8, {-40.0f, 1.0f}, 0.5f};
    effects::Camera cam = effects::make_camera(sim::CameraView{{0.0f, 4.0f, -2.0f}, {0.0f, 0.0f, 30.0f}}, 1.6f);
    effects::LodView view;
    view.view_proj = cam.view_proj;
    view.eye = cam.eye;
    view.pixels_per_radian = 0.5f * cam.proj[1][1] * 720.0f;
    auto tiles = effects::plan_tiles(l, view);
    ASSERT_FALSE(tiles.empty());
    EXPECT_LT(tiles.size(), 64u) << "tiles behind the eye are skipped";
    std::map<std::pair<int, int>, effects::TileDraw> by_tile;
    int finest = 64, coarsest = 0;
    for (const auto& t : tiles) {
        by_tile[{t.tile.x, t.tile.y}] = t;
        finest = std::min(finest, t.stride);
        coarsest = std::max(coarsest, t.stride);
        // Each edge at least as coarse as the tile, and the lattice border at tile corners.
        for (int e = 0; e < 4; ++e) EXPECT_GE(t.edge_stride[e], t.stride);
        if (t.tile.y == 0) {
            EXPECT_EQ(t.edge_stride[0], 32);
        }
        if (t.tile.x == 7) {
            EXPECT_EQ(t.edge_stride[1], 32);
        }
    }
    EXPECT_EQ(finest, 1) << "the tile under the eye is drawn at full detail";
    EXPECT_GE(coarsest, 4) << "far tiles are coarser";
    for (const auto& [key, t] : by_tile) {
        auto right = by_tile.find({key.first + 1, key.second});
        if (right != by_tile.end()) {
            EXPECT_EQ(t.edge_stride[1], right->second.edge_stride[3]);
        }
        auto up = by_tile.find({key.first, key.second + 1});
        if (up != by_tile.end()) {
            EXPECT_EQ(t.edge_stride[2], up->second.edge_stride[0]);
        }
    }
}

TEST(SplashSheetMesh, OnlyTrianglesWithThreeAirborneCornersWithUpwardNormalsAtRest) {
    const int n = 6;
    std::vector<glm::vec3> pos;
    std::vector<uint8_t> air(size_t(n * n), 0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) pos.push_back({float(i) * 0.1f, 0.0f, float(j) * 0.1f});
    effects::SplashSheetMesh mesh;
    mesh.append({n, 0.1f, pos, air}, 6.0f, 0.0f);
    EXPECT_TRUE(mesh.vertices.empty()) << "a sheet with nothing in the air adds nothing";

    // A 3x3 block of airborne vertices: 2x2 quads, 8 triangles.
    for (int j = 1; j <= 3; ++j)
        for (int i = 1; i <= 3; ++i) air[size_t(j * n + i)] = 1;
    // A lone airborne vertex and an airborne pair add no triangle.
    air[size_t(5 * n + 5)] = 1;
    air[size_t(0 * n + 4)] = air[size_t(0 * n + 5)] = 1;
    mesh.append({n, 0.1f, pos, air}, 6.0f, 0.0f);
    EXPECT_EQ(mesh.indices.size(), 8u * 3u);
    ASSERT_EQ(mesh.vertices.size(), size_t(n * n));
    for (uint32_t idx : mesh.indices) EXPECT_TRUE(air[idx]) << "triangle corner " << idx << " is not airborne";
    for (const effects::SheetVertex& v : mesh.vertices) {
        EXPECT_NEAR(v.normal.y, 1.0f, 1e-6f);
        EXPECT_NEAR(v.stretch, 1.0f, 1e-5f);
    }
    // Cover: the block's centre has all six of its triangles, the edges and corners fewer.
    EXPECT_FLOAT_EQ(mesh.vertices[size_t(2 * n + 2)].cover, 1.0f);
    EXPECT_FLOAT_EQ(mesh.vertices[size_t(2 * n + 1)].cover, 3.0f / 6.0f);  // on an edge
    EXPECT_FLOAT_EQ(mesh.vertices[size_t(1 * n + 1)].cover, 2.0f / 6.0f);  // the corner on the diagonal
    EXPECT_FLOAT_EQ(mesh.vertices[size_t(1 * n + 3)].cover, 1.0f / 6.0f);  // the other corner
    EXPECT_FLOAT_EQ(mesh.vertices[size_t(5 * n + 5)].cover, 0.0f);

    // A second sheet's indices point past the first's vertices.
    mesh.append({n, 0.1f, pos, air}, 6.0f, 0.0f);
    EXPECT_EQ(mesh.indices.size(), 16u * 3u);
    EXPECT_EQ(mesh.indices[24], uint32_t(n * n) + mesh.indices[0]);

    // Fling one corner of the block far away: the triangles it stretches past the tear
    // are left out, the others stay.
    mesh.clear();
    pos[size_t(3 * n + 3)] += glm::vec3(6.0f, 4.0f, 6.0f);
    mesh.append({n, 0.1f, pos, air}, 6.0f, 0.0f);
    EXPECT_LT(mesh.indices.size(), 8u * 3u);
    EXPECT_GE(mesh.indices.size(), 5u * 3u);
    for (uint32_t idx : mesh.indices) EXPECT_TRUE(air[idx]);
    EXPECT_GT(mesh.vertices[size_t(2 * n + 3)].stretch, 10.0f) << "its neighbour sees the film stretched";
    EXPECT_LT(mesh.vertices[size_t(2 * n + 2)].cover, 1.0f) << "the tear's edge runs past the block's centre";
}

TEST_F(WaterRenderTest, WithoutAGridTheFlatSeaLiesAtSeaLevel) {
    WaterView flat;
    render(&flat);
    auto hdr = stage_->hdr();
    EXPECT_EQ(non_finite_values(hdr), 0u);
    auto depth = stage_->depth();
    // Rows below the quay's edge see water: it must be at y = 0 and not the sea bed.
    int water_pixels = 0;
    for (int y = kHeight / 2; y < kHeight; y += 7)
        for (int x = 0; x < kWidth; x += 7) {
            glm::vec3 p = world_at(depth, x, y);
            if (p.z < 0.5f) continue;  // the quay
            ++water_pixels;
            EXPECT_NEAR(p.y, 0.0f, 0.02f) << "pixel " << x << "," << y;
        }
    EXPECT_GT(water_pixels, 100);
    maybe_write_png("flat_sea", stage_->ldr());
}

TEST_F(WaterRenderTest, AWorldWithoutWaterSimDrawsTheSameFlatSea) {
    ASSERT_EQ(stage_->world().find<sim::WaterSim>(), nullptr) << "the test level has no wave grid";
    WaterView flat;
    render(&flat);
    auto expected = stage_->ldr();
    render(nullptr);
    EXPECT_EQ(pixels_differing(stage_->ldr(), expected, 0), 0);
}

TEST_F(WaterRenderTest, WindRipplesMoveWithTime) {
    water_pass().look().ripples = 1.0f;
    WaterView flat;
    render(&flat, 0.0);
    auto at_0 = stage_->ldr();
    render(&flat, 0.5);
    auto at_half = stage_->ldr();
    glm::ivec2 c = pixel_of({10.0f, 0.0f, 8.0f});
    EXPECT_GT(pixels_differing(at_0, at_half, 2, c - glm::ivec2(30), c + glm::ivec2(30)), 300);
    water_pass().look().ripples = 0.0f;
    render(&flat, 0.0);
    auto still_0 = stage_->ldr();
    render(&flat, 0.5);
    EXPECT_EQ(pixels_differing(still_0, stage_->ldr(), 0), 0) << "without ripples a flat sea does not change";
}

TEST_F(WaterRenderTest, AGridAtRestLooksLikeTheFlatSea) {
    WaterView flat;
    render(&flat);
    auto flat_image = stage_->ldr();
    TestGrid grid;
    WaterView view;
    view.grid = grid.view();
    render(&view);
    auto grid_image = stage_->ldr();
    maybe_write_png("grid_at_rest", grid_image);
    // Different triangles, same surface: at most a few rounding differences, no seams.
    EXPECT_LE(pixels_differing(grid_image, flat_image, 2), kWidth * kHeight / 1000);
}

TEST_F(WaterRenderTest, ARingWaveOnTheGridShowsAndRaisesTheSurface) {
    WaterView flat;
    render(&flat);
    auto flat_image = stage_->ldr();

    // The sim's own grid, pushed down and left to run: a crater that spreads as a ring.
    sim::WaveGridParams params;
    params.size = 128;
    params.spacing_m = 0.25f;
    params.origin_xz = {-6.0f, 2.0f};
    sim::WaveGrid grid(params, sim::kTickSeconds);
    const glm::vec2 centre{10.0f, 12.0f};
    grid.push(centre, 1.5f, 0.4f);
    for (int t = 0; t < 45; ++t) grid.step();
    WaterView view;
    view.grid = WaveHeights{grid.size(), grid.spacing(), grid.origin(), grid.heights()};
    render(&view);
    auto img = stage_->ldr();
    maybe_write_png("grid_ring", img);
    EXPECT_EQ(non_finite_values(stage_->hdr()), 0u);

    glm::ivec2 c = pixel_of({centre.x, 0.0f, centre.y});
    const int half = 30;
    EXPECT_GT(window_difference_variance(img, flat_image, c, half), 10.0f) << "the ring should vary the water's shade";
    EXPECT_GT(pixels_differing(img, flat_image, 6, c - glm::ivec2(half), c + glm::ivec2(half)), half * half / 4);
    // Away from the ring the sea is unchanged.
    glm::ivec2 far = pixel_of({centre.x - 11.0f, 0.0f, centre.y + 14.0f});
    EXPECT_LE(pixels_differing(img, flat_image, 2, far - glm::ivec2(5), far + glm::ivec2(5)), 3);

    // The surface in the depth buffer follows the grid: the crest stands above sea level.
    float crest = *std::max_element(grid.heights().begin(), grid.heights().end());
    ASSERT_GT(crest, 0.03f);
    auto depth = stage_->depth();
    float highest = -1.0f;
    for (int dy = -half; dy <= half; ++dy)
        for (int dx = -half; dx <= half; ++dx)
            highest = std::max(highest, world_at(depth, c.x + dx, c.y + dy).y);
    EXPECT_GT(highest, 0.5f * crest);
    EXPECT_LT(highest, 1.2f * crest + 0.01f);
}

TEST_F(WaterRenderTest, TilesOfDifferentStridesMeetWithoutCracks) {
    // A rough sea (the worst case for a crack) drawn with coarse far tiles.
    TestGrid grid;
    uint32_t state = 12345u;
    for (float& h : grid.heights) {
        state = state * 1664525u + 1013904223u;
        h = (float(state >> 8) / 16777216.0f - 0.5f) * 0.5f;
    }
    WaterView view;
    view.grid = grid.view();
    water_pass().look().triangle_px = 24.0f;
    render(&view);
    maybe_write_png("rough_grid", stage_->ldr());
    std::set<int> strides;
    for (const effects::TileDraw& t : water_pass().surface_tiles()) strides.insert(t.stride);
    ASSERT_GE(strides.size(), 2u) << "the view should mix tile strides";

    // A crack shows what lies below the surface: the sea bed, metres down.
    auto depth = stage_->depth();
    const glm::vec2 lo = grid.origin + 0.3f, hi = grid.origin + float(grid.size - 1) * grid.spacing - 0.3f;
    int inside = 0, cracks = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            glm::vec3 p = world_at(depth, x, y);
            // Where the eye ray crosses sea level, to know the pixel looks at the grid.
            glm::vec3 d = glm::normalize(p - camera_.eye);
            if (d.y > -1e-3f) continue;
            glm::vec3 at_sea = camera_.eye + d * (-camera_.eye.y / d.y);
            if (at_sea.x < lo.x || at_sea.z < lo.y || at_sea.x > hi.x || at_sea.z > hi.y) continue;
            ++inside;
            if (p.y < -0.6f) ++cracks;
        }
    EXPECT_GT(inside, kWidth * kHeight / 10);
    EXPECT_EQ(cracks, 0);
    EXPECT_EQ(non_finite_values(stage_->hdr()), 0u);
}

TEST_F(WaterRenderTest, ASplashSheetIsDrawnWhereItIsAirborne) {
    WaterView flat;
    render(&flat);
    auto flat_image = stage_->ldr();

    // A crown: a sheet around (10, 12) whose ring of vertices stands up to 0.8 m high.
    const int n = 40;
    const float spacing = 0.08f;
    const glm::vec2 centre{10.0f, 12.0f};
    std::vector<glm::vec3> pos;
    std::vector<uint8_t> air;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            glm::vec2 d = (glm::vec2(i, j) - glm::vec2(float(n - 1) * 0.5f)) * spacing;
            float r = glm::length(d);
            float lift = r > 0.6f && r < 1.4f ? 0.8f * std::sin((r - 0.6f) / 0.8f * 3.14159f) : -0.03f;
            glm::vec2 out = r > 1e-4f ? d / r * (lift > 0.0f ? lift * 0.6f : 0.0f) : glm::vec2(0.0f);
            pos.push_back({centre.x + d.x + out.x, lift, centre.y + d.y + out.y});
            air.push_back(lift > 0.0f ? 1 : 0);
        }
    WaterView view;
    view.sheets.push_back({n, spacing, pos, air});
    render(&view);
    auto img = stage_->ldr();
    maybe_write_png("splash_sheet", img);
    EXPECT_EQ(non_finite_values(stage_->hdr()), 0u);
    EXPECT_GT(water_pass().sheet_triangles(), 500u);

    glm::ivec2 c = pixel_of({centre.x, 0.4f, centre.y});
    EXPECT_GT(pixels_differing(img, flat_image, 8, c - glm::ivec2(20), c + glm::ivec2(20)), 200);
    // The crown stands in the depth buffer.
    auto depth = stage_->depth();
    float highest = -1.0f;
    for (int dy = -25; dy <= 25; ++dy)
        for (int dx = -25; dx <= 25; dx += 5) highest = std::max(highest, world_at(depth, c.x + dx, c.y + dy).y);
    EXPECT_GT(highest, 0.5f);
}

TEST_F(WaterRenderTest, SprayBrightensWithoutWritingDepthAndTinyDropsStillShow) {
    WaterView view;
    render(&view);
    auto before = stage_->ldr();
    auto depth_before = stage_->depth();

    // A cloud of drops above the water, and one 1 mm drop far out.
    const glm::vec3 centre{10.0f, 1.0f, 12.0f};
    for (int k = 0; k < 400; ++k) {
        float a = float(k) * 2.39996f, r = 0.02f * std::sqrt(float(k));
        view.spray.push_back({centre + glm::vec3(r * std::cos(a), 0.3f * std::sin(float(k)), r * std::sin(a)), 0.01f});
    }
    const glm::vec3 far_drop{30.0f, 3.0f, 90.0f};
    view.spray.push_back({far_drop, 0.001f});
    render(&view);
    auto after = stage_->ldr();
    maybe_write_png("spray", after);
    EXPECT_EQ(non_finite_values(stage_->hdr()), 0u);
    EXPECT_EQ(stage_->depth(), depth_before) << "spray must not write depth";

    glm::ivec2 c = pixel_of(centre);
    double gain = 0.0;
    for (int y = c.y - 6; y <= c.y + 6; ++y)
        for (int x = c.x - 6; x <= c.x + 6; ++x) gain += luminance(after, x, y) - luminance(before, x, y);
    // Drops are clear lenses toned like the sky they refract, not white: a dense cloud
    // still brightens the darker water clearly.
    EXPECT_GT(gain / (13.0 * 13.0), 5.0) << "the spray cloud should brighten the water behind it";
    glm::ivec2 f = pixel_of(far_drop);
    EXPECT_GE(pixels_differing(after, before, 0, f - glm::ivec2(2), f + glm::ivec2(3)), 1)
        << "a drop far smaller than a pixel is still drawn";
}

TEST_F(WaterRenderTest, InconsistentViewsAreRefusedWithAClearMessage) {
    std::vector<float> heights(100, 0.0f);
    WaterView view;
    view.grid = WaveHeights{16, 0.5f, {0.0f, 0.0f}, heights};
    try {
        render(&view);
        FAIL() << "a 16x16 grid with 100 heights was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("wave grid of size 16 has 100 heights"), std::string::npos) << e.what();
    }
    view.grid = WaveHeights{10, 0.0f, {0.0f, 0.0f}, heights};
    EXPECT_THROW(render(&view), std::invalid_argument);
    view.grid.reset();
    std::vector<glm::vec3> pos(9);
    std::vector<uint8_t> air(8);
    view.sheets.push_back({3, 0.1f, pos, air});
    try {
        render(&view);
        FAIL() << "a sheet with 8 airborne flags for 9 vertices was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("splash sheet 0"), std::string::npos) << e.what();
    }
}

TEST_F(WaterRenderTest, AStoneThrownIntoTheWaterSimMakesARingASplashAndSpray) {
    use_world(std::make_unique<sim::World>(make_test_level(), sim::standard_subsystems_with_water({}, 99)));
    sim::World& world = stage_->world();
    const sim::WaterSim* water = &world.get<sim::WaterSim>();
    sim::CameraView close;  // near the quay, looking out at where the stone lands
    close.eye = {10.0f, 2.5f, 4.0f};
    close.target = {10.0f, 0.3f, 12.0f};
    camera_ = stage_->camera(close);
    render(nullptr);
    auto before = stage_->ldr();

    // A stone thrown south from the quay: it enters the water about 12 m out.
    world.get<sim::ThrownObjects>().launch(sim::ThrownObjects::kHeavy, {10.0f, 2.5f, -1.5f}, {0.0f, 0.0f, 1.0f},
                                           glm::vec3(0.0f));
    int splash_tick = -1;
    glm::vec3 entry{0.0f};
    for (int t = 0; t < 180 && splash_tick < 0; ++t) {
        world.step(sim::TickInput{});
        if (!water->splashes().empty()) {
            splash_tick = t;
            entry = water->splashes().front().position;
        }
    }
    ASSERT_GE(splash_tick, 0) << "the stone never splashed";
    for (int t = 0; t < 12; ++t) world.step(sim::TickInput{});  // the crown rises
    ASSERT_FALSE(water->spray().particles().empty());
    const auto& heights = water->grid().heights();
    ASSERT_LT(*std::min_element(heights.begin(), heights.end()), -0.005f) << "the impact should dent the grid";

    render(nullptr);
    auto img = stage_->ldr();
    maybe_write_png("stone_splash", img);
    EXPECT_EQ(non_finite_values(stage_->hdr()), 0u);
    EXPECT_GT(water_pass().sheet_triangles(), 0u) << "the crown should be in the air 12 ticks after the splash";

    glm::ivec2 c = pixel_of(entry);
    const int half = 25;
    EXPECT_GT(window_difference_variance(img, before, c, half), 20.0f);
    EXPECT_GT(pixels_differing(img, before, 8, c - glm::ivec2(half), c + glm::ivec2(half)), half * half / 2);
}
