// The upscale of dynamic resolution (shaders/scene/upscale.frag.glsl), on a headless
// context: flat stays flat, a smooth ramp stays smooth, an edge comes out steeper than
// bilinear when asked, and nothing overshoots the source's range (no ringing).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "HeadlessTest.h"
#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "game/capture/Readback.h"

namespace {

using effects::gl::Framebuffer;
using effects::gl::Program;
using effects::gl::Texture;

class UpscaleTest : public HeadlessTest {
protected:
    // `source` (w x h grey levels, row 0 at the bottom) upscaled 2x; the red channel of
    // the result, rows top-down.
    std::vector<int> upscale(const std::vector<uint8_t>& grey, int w, int h, float edge) {
        std::vector<uint8_t> rgba;
        for (uint8_t g : grey) rgba.insert(rgba.end(), {g, g, g, 255});
        Texture source = Texture::create_2d("test.display", GL_RGBA8, w, h);
        source.set_filter(GL_LINEAR, GL_LINEAR);  // as SceneTargets' display and history
        source.set_wrap(GL_CLAMP_TO_EDGE);
        glTextureSubImage2D(source.id(), 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        Texture out = Texture::create_2d("test.output", GL_RGBA8, 2 * w, 2 * h);
        Framebuffer fbo = Framebuffer::create("test.output");
        fbo.attach_colour(0, out);
        fbo.check_complete();
        fbo.bind();
        glViewport(0, 0, 2 * w, 2 * h);
        const Program p =
            Program::from_files("upscale", {"common/fullscreen.vert.glsl", "scene/upscale.frag.glsl"});
        p.use();
        p.set("u_display", 0);
        p.set("u_edge", edge);
        source.bind(0);
        effects::gl::bind_empty_vertex_array();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        const game::ImageRGBA8 image = game::read_framebuffer_rgba8(fbo.id(), 2 * w, 2 * h);
        std::vector<int> red;
        for (size_t i = 0; i < image.pixels.size(); i += 4) red.push_back(image.pixels[i]);
        return red;
    }

};

constexpr int W = 16, H = 8;

// Pixels of one output row strictly between the two sides of a vertical edge.
int transition_pixels(const std::vector<int>& row_major, int row, int dark, int light) {
    int n = 0;
    for (int x = 0; x < 2 * W; ++x) {
        const int v = row_major[size_t(row * 2 * W + x)];
        if (v > dark + 2 && v < light - 2) ++n;
    }
    return n;
}

}  // namespace

TEST_F(UpscaleTest, FlatStaysFlat) {
    for (int level : {0, 77, 255}) {
        const std::vector<int> out = upscale(std::vector<uint8_t>(W * H, uint8_t(level)), W, H, 1.0f);
        for (int v : out) ASSERT_EQ(v, level);
    }
}

TEST_F(UpscaleTest, AnEdgeComesOutSteeperThanBilinearWithoutOvershoot) {
    std::vector<uint8_t> step(W * H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) step[size_t(y * W + x)] = x < W / 2 ? 30 : 220;
    const std::vector<int> bilinear = upscale(step, W, H, 0.0f);
    const std::vector<int> ours = upscale(step, W, H, 1.0f);
    EXPECT_GE(transition_pixels(bilinear, H, 30, 220), 2) << "bilinear blends across the edge";
    EXPECT_LT(transition_pixels(ours, H, 30, 220), transition_pixels(bilinear, H, 30, 220));
    for (int v : ours) {
        ASSERT_GE(v, 30);
        ASSERT_LE(v, 220);
    }
}

TEST_F(UpscaleTest, ASmoothRampStaysASmoothMonotoneRamp) {
    std::vector<uint8_t> ramp(W * H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) ramp[size_t(y * W + x)] = uint8_t(60 + 4 * x);
    const std::vector<int> bilinear = upscale(ramp, W, H, 0.0f);
    const std::vector<int> ours = upscale(ramp, W, H, 0.25f);
    for (int x = 1; x < 2 * W; ++x) {
        const size_t i = size_t(H * 2 * W + x);
        EXPECT_GE(ours[i], ours[i - 1]) << "x " << x;
        EXPECT_LE(ours[i] - ours[i - 1], 4) << "no steps in a gentle ramp, x " << x;
        EXPECT_NEAR(ours[i], bilinear[i], 2) << "a gentle ramp stays near the bilinear, x " << x;
    }
}
