// The frame's one scene copy (SceneTargets) on a headless context: a refresh of a
// rectangle holds the scene colour there and leaves the rest of the copy as it was; a
// refresh with mips holds the scene in its base level and its average in the last; after
// the targets are re-created at another size and back, the copies still hold the scene,
// and every re-creation gives a new generation.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include <glm/vec2.hpp>

#include "HeadlessTest.h"
#include "effects/scene/SceneTargets.h"

namespace {

using effects::SceneTargets;

// Values a half float holds exactly, different at every pixel nearby and for each seed.
std::vector<float> pattern(int w, int h, int seed) {
    std::vector<float> rgba(size_t(w * h * 4));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = &rgba[size_t((y * w + x) * 4)];
            p[0] = float((x * 7 + y * 13 + seed * 31) % 64) / 8.0f;
            p[1] = float((x * 3 + y * 5 + seed * 11) % 32) / 4.0f;
            p[2] = float(seed);
            p[3] = 1.0f;
        }
    return rgba;
}

void paint(const effects::gl::Texture& t, const std::vector<float>& rgba) {
    glTextureSubImage2D(t.id(), 0, 0, 0, t.width(), t.height(), GL_RGBA, GL_FLOAT, rgba.data());
}

std::vector<float> read(const effects::gl::Texture& t, int level = 0) {
    const int w = std::max(t.width() >> level, 1), h = std::max(t.height() >> level, 1);
    std::vector<float> rgba(size_t(w * h * 4));
    glGetTextureImage(t.id(), level, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
    return rgba;
}

class SceneCopyTest : public HeadlessTest {};

TEST_F(SceneCopyTest, ARectangleRefreshHoldsTheSceneThereAndLeavesTheRest) {
    constexpr int W = 96, H = 64;
    SceneTargets t;
    t.resize(W, H);
    const std::vector<float> before = pattern(W, H, 1), after = pattern(W, H, 2);
    paint(t.colour(), before);
    t.copy_scene();
    paint(t.colour(), after);
    const glm::ivec4 rect{20, 10, 57, 41};
    t.refresh_colour_copy(rect);
    const std::vector<float> copy = read(t.colour_copy());
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    int inside = 0, outside = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const bool in = x >= rect.x && x < rect.z && y >= rect.y && y < rect.w;
            const std::vector<float>& want = in ? after : before;
            (in ? inside : outside)++;
            for (int c = 0; c < 4; ++c) {
                const size_t i = size_t((y * W + x) * 4 + c);
                ASSERT_EQ(copy[i], want[i]) << "pixel " << x << ", " << y << " channel " << c
                                            << (in ? " inside" : " outside") << " the rectangle";
            }
        }
    EXPECT_EQ(inside, 37 * 31);
    EXPECT_GT(outside, inside);
    // An empty rectangle copies nothing.
    paint(t.colour(), pattern(W, H, 3));
    t.refresh_colour_copy({30, 30, 30, 40});
    EXPECT_EQ(read(t.colour_copy()), copy);
}

TEST_F(SceneCopyTest, TheMipRefreshHoldsTheSceneAndItsAverage) {
    constexpr int W = 64, H = 32;
    SceneTargets t;
    t.resize(W, H);
    // Left half 4, right half 0 in red: the last level (1x1) averages to 2.
    std::vector<float> scene = pattern(W, H, 4);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) scene[size_t((y * W + x) * 4)] = x < W / 2 ? 4.0f : 0.0f;
    paint(t.colour(), scene);
    t.refresh_colour_copy_with_mips();
    EXPECT_EQ(read(t.colour_copy()), scene);
    const int last = t.colour_copy().levels() - 1;
    ASSERT_EQ(last, 6);
    const std::vector<float> top = read(t.colour_copy(), last);
    ASSERT_EQ(top.size(), 4u);
    EXPECT_NEAR(top[0], 2.0f, 0.01f);
    EXPECT_NEAR(top[2], 4.0f, 0.01f);  // the seed's blue, everywhere
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SceneCopyTest, ResizingThereAndBackKeepsTheCopiesWorking) {
    SceneTargets t;
    std::vector<uint64_t> generations;
    int seed = 5;
    for (glm::ivec2 size : {glm::ivec2(80, 48), glm::ivec2(40, 24), glm::ivec2(80, 48)}) {
        t.resize(size.x, size.y);
        generations.push_back(t.generation());
        t.resize(size.x, size.y);  // the same size again: nothing re-created
        EXPECT_EQ(t.generation(), generations.back());
        ASSERT_EQ(t.colour_copy().width(), size.x);
        ASSERT_EQ(t.colour_copy().levels(), effects::gl::Texture::full_mip_levels(size.x, size.y));

        const std::vector<float> scene = pattern(size.x, size.y, seed++);
        paint(t.colour(), scene);
        t.copy_scene();
        EXPECT_EQ(read(t.colour_copy()), scene) << size.x << "x" << size.y;
        const std::vector<float> later = pattern(size.x, size.y, seed++);
        paint(t.colour(), later);
        t.refresh_colour_copy_with_mips();
        EXPECT_EQ(read(t.colour_copy()), later) << size.x << "x" << size.y;
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
    EXPECT_LT(generations[0], generations[1]);
    EXPECT_LT(generations[1], generations[2]);
}

}  // namespace
