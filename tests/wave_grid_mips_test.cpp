// The wave grid's texels as the water's shaders read them (effects/water/WaveGridMips):
// slopes and Laplacian from central differences (one-sided on the border), the height in
// w, and a mip chain of 2x2 averages down to one texel, for grids of even and odd sizes.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "effects/water/WaveGridMips.h"

namespace {

effects::WaveHeights grid_of(const std::vector<float>& heights, int size, float spacing) {
    return {size, spacing, {0.0f, 0.0f}, heights};
}

std::vector<float> heights_of(int size, float spacing, float (*h)(float, float)) {
    std::vector<float> out(size_t(size) * size);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) out[size_t(j) * size + i] = h(float(i) * spacing, float(j) * spacing);
    return out;
}

TEST(WaveGridMips, APlaneHasItsSlopeEverywhereAndNoCurvature) {
    const int n = 16;
    const float spacing = 0.5f;
    const auto heights = heights_of(n, spacing, [](float x, float z) { return 0.25f * x - 0.125f * z + 1.0f; });
    effects::WaveGridMips mips;
    mips.derive(grid_of(heights, n, spacing));
    ASSERT_EQ(mips.levels(), 5);  // 16, 8, 4, 2, 1
    for (int level = 0; level < mips.levels(); ++level) {
        const auto texels = mips.level(level);
        ASSERT_EQ(texels.size(), size_t(mips.level_size(level) * mips.level_size(level)));
        for (const glm::vec4& t : texels) {
            EXPECT_NEAR(t.x, 0.25f, 1e-5f) << "level " << level;
            EXPECT_NEAR(t.y, -0.125f, 1e-5f) << "level " << level;
        }
    }
    // No curvature inside (the border's Laplacian counts its own height for the missing
    // neighbour, as the slopes' one-sided differences do).
    for (int j = 1; j < n - 1; ++j)
        for (int i = 1; i < n - 1; ++i) EXPECT_NEAR(mips.level(0)[size_t(j) * n + i].z, 0.0f, 1e-4f);
    // Heights are the cells' own at level 0.
    EXPECT_FLOAT_EQ(mips.level(0)[size_t(3) * n + 5].w, heights[size_t(3) * n + 5]);
}

TEST(WaveGridMips, ABowlHasItsCurvatureInsideAndOneSidedSlopesOnTheBorder) {
    const int n = 8;
    const float spacing = 2.0f;
    const auto heights = heights_of(n, spacing, [](float x, float z) { return 0.5f * x * x + z; });
    effects::WaveGridMips mips;
    mips.derive(grid_of(heights, n, spacing));
    const auto t = mips.level(0);
    // Inside: dh/dx = x exactly for central differences of a parabola, Laplacian = 1.
    const glm::vec4 inner = t[size_t(4) * n + 3];
    EXPECT_NEAR(inner.x, 3.0f * spacing, 1e-4f);
    EXPECT_NEAR(inner.y, 1.0f, 1e-5f);
    EXPECT_NEAR(inner.z, 1.0f, 1e-4f);
    // First column: the one-sided difference (h(1) - h(0)) / spacing = spacing / 2.
    EXPECT_NEAR(t[size_t(4) * n + 0].x, 0.5f * spacing, 1e-5f);
}

TEST(WaveGridMips, EachLevelAveragesTwoByTwoOfTheOneBelowAndOddSizesRepeatTheirLastRow) {
    const int n = 5;  // levels 5, 2, 1
    std::vector<float> heights(size_t(n) * n);
    for (size_t k = 0; k < heights.size(); ++k) heights[k] = float(k);
    effects::WaveGridMips mips;
    mips.derive(grid_of(heights, n, 1.0f));
    ASSERT_EQ(mips.levels(), 3);
    const auto l0 = mips.level(0), l1 = mips.level(1), l2 = mips.level(2);
    ASSERT_EQ(l1.size(), 4u);
    ASSERT_EQ(l2.size(), 1u);
    auto at0 = [&](int i, int j) { return l0[size_t(j) * n + i]; };
    EXPECT_FLOAT_EQ(l1[0].w, 0.25f * (at0(0, 0).w + at0(1, 0).w + at0(0, 1).w + at0(1, 1).w));
    EXPECT_FLOAT_EQ(l1[3].w, 0.25f * (at0(2, 2).w + at0(3, 2).w + at0(2, 3).w + at0(3, 3).w));
    EXPECT_FLOAT_EQ(l2[0].w, 0.25f * (l1[0].w + l1[1].w + l1[2].w + l1[3].w));
    // A new size re-lays the chain.
    mips.derive(grid_of(std::vector<float>(1, 2.0f), 1, 1.0f));
    ASSERT_EQ(mips.levels(), 1);
    EXPECT_EQ(mips.level(0)[0], glm::vec4(0.0f, 0.0f, 0.0f, 2.0f));
}

}  // namespace
