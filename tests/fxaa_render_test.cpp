// The frame's anti-aliasing (FxaaPass, shaders/scene/fxaa.frag.glsl) through the real
// tone map, FXAA and upscale passes on a headless context: a hard, slightly slanted edge
// in the scene colour comes out with stair-steps without it and as a smooth ramp with
// it, also through the upscale of a smaller scene, and flat colour away from edges is
// left exactly as it was.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "SimTestLevel.h"

namespace {

constexpr int W = 160, H = 96;
constexpr float kDark = 0.03f, kBright = 0.8f;  // HDR radiance on either side of the edge

class FxaaRenderTest : public HeadlessTest {
protected:
    // The scene colour holds a hard edge (every pixel either side, as a rasteriser
    // draws it) along y = y0 + slope * x (GL rows), bright below it; the tone-mapped,
    // optionally anti-aliased output's red channel, rows bottom-up.
    // `scene_scale` below 1: the scene drawn smaller and upscaled to the output, the
    // edge in the scene's pixels.
    std::vector<float> render_edge(bool antialias, float y0, float slope, int scene_scale_div = 1) {
        RenderStage stage(make_test_level(),
                          {.width = W, .height = H, .passes = kTonemapPass | kFxaaPass | kUpscalePass});
        const int w = W / scene_scale_div, h = H / scene_scale_div;
        stage.renderer().set_render_scale(1.0f / float(scene_scale_div));
        stage.renderer().size_scene(W, H);  // the scene's targets, w x h, before the edge goes in
        std::vector<float> hdr(size_t(w * h * 4));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const bool below = float(y) + 0.5f < y0 + slope * (float(x) + 0.5f);
                const float v = below ? kBright : kDark;
                float* px = &hdr[size_t((y * w + x) * 4)];
                px[0] = px[1] = px[2] = v;
                px[3] = 1.0f;
            }
        glTextureSubImage2D(stage.targets().colour().id(), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, hdr.data());
        stage.resources().quality.antialias = antialias;
        const game::ImageRGBA8 image = stage.render(sim::CameraView{});
        std::vector<float> red(size_t(W * H));
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) red[size_t(y * W + x)] = image.pixels[size_t(((H - 1 - y) * W + x) * 4)];
        return red;
    }
};

// The edge's height in each column: the bright share of the column, in pixels.
std::vector<double> edge_heights(const std::vector<float>& red) {
    float lo = 255.0f, hi = 0.0f;
    for (float v : red) lo = std::min(lo, v), hi = std::max(hi, v);
    std::vector<double> heights(W, 0.0);
    for (int x = 0; x < W; ++x)
        for (int y = 0; y < H; ++y) heights[size_t(x)] += (red[size_t(y * W + x)] - lo) / (hi - lo);
    return heights;
}

// How far the edge's height strays from the true edge (y0 + slope * x at the column's
// centre): a staircase strays up to half a pixel, a ramp much less.
double mean_error(const std::vector<double>& heights, float y0, float slope, int from, int to) {
    double sum = 0.0;
    for (int x = from; x < to; ++x) sum += std::abs(heights[size_t(x)] - (y0 + slope * (float(x) + 0.5f)));
    return sum / double(to - from);
}

// The tallest stair: the largest change of the edge's height from one column to the next
// (a whole pixel for a hard edge, the slope itself for a perfect ramp).
double tallest_step(const std::vector<double>& heights, int from, int to) {
    double tallest = 0.0;
    for (int x = from + 1; x < to; ++x) tallest = std::max(tallest, std::abs(heights[size_t(x)] - heights[size_t(x - 1)]));
    return tallest;
}

int intermediate_pixels(const std::vector<float>& red) {
    float lo = 255.0f, hi = 0.0f;
    for (float v : red) lo = std::min(lo, v), hi = std::max(hi, v);
    int n = 0;
    for (float v : red)
        if (v > lo + 8.0f && v < hi - 8.0f) ++n;
    return n;
}

}  // namespace

TEST_F(FxaaRenderTest, ASlantedEdgeLosesItsStairSteps) {
    // A rise of one pixel in 12: a staircase of long treads, what FXAA is made for.
    const float slope = 1.0f / 12.0f, y0 = 40.0f;
    const std::vector<float> off = render_edge(false, y0, slope);
    const std::vector<float> on = render_edge(true, y0, slope);
    EXPECT_EQ(intermediate_pixels(off), 0) << "without anti-aliasing the edge is hard";
    EXPECT_GE(intermediate_pixels(on), W) << "with it, about a pixel or more of ramp a column";
    // Away from the image's sides, where the walk along the edge runs out of image.
    const std::vector<double> hard = edge_heights(off), smooth = edge_heights(on);
    const int from = 16, to = W - 16;
    EXPECT_GT(tallest_step(hard, from, to), 0.95) << "whole-pixel stairs without it";
    EXPECT_LT(tallest_step(smooth, from, to), 0.4) << "no stair of more than 0.4 pixel with it";
    const double error_off = mean_error(hard, y0, slope, from, to), error_on = mean_error(smooth, y0, slope, from, to);
    EXPECT_GT(error_off, 0.2) << "a staircase strays a quarter pixel on average";
    EXPECT_LT(error_on, 0.4 * error_off) << "off " << error_off << ", on " << error_on;
}

TEST_F(FxaaRenderTest, FlatColourIsLeftAsItWas) {
    const std::vector<float> off = render_edge(false, 40.0f, 1.0f / 12.0f);
    const std::vector<float> on = render_edge(true, 40.0f, 1.0f / 12.0f);
    // Rows far from the edge (it spans rows 40 to 54).
    for (int y : {0, 10, 25, 70, 85, 95})
        for (int x = 0; x < W; ++x)
            ASSERT_EQ(on[size_t(y * W + x)], off[size_t(y * W + x)]) << "pixel " << x << ", " << y;
}

TEST_F(FxaaRenderTest, BelowScaleOneTheUpscaleShowsTheAntialiasedEdge) {
    // The scene at half the output's size: the edge's stairs are two output pixels tall.
    const float slope = 1.0f / 12.0f, y0 = 20.0f;
    const std::vector<float> off = render_edge(false, y0, slope, 2);
    const std::vector<float> on = render_edge(true, y0, slope, 2);
    const std::vector<double> hard = edge_heights(off), smooth = edge_heights(on);
    const int from = 32, to = W - 32;
    // In output pixels: the true edge is twice as high.
    const double error_off = mean_error(hard, 2.0f * y0, slope, from, to);
    const double error_on = mean_error(smooth, 2.0f * y0, slope, from, to);
    EXPECT_GT(tallest_step(hard, from, to), 1.5) << "two-pixel stairs without it";
    EXPECT_LT(tallest_step(smooth, from, to), 0.8);
    EXPECT_LT(error_on, 0.6 * error_off) << "off " << error_off << ", on " << error_on;
}
