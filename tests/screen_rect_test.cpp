// The screen rectangle of a world box (what the fluid pass scissors to): a box in view
// gets its projected bounds, one that straddles the eye only the part in front of the
// near plane, one behind the eye nothing.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "effects/scene/ScreenRect.h"

namespace {

constexpr int W = 1280, H = 720;
constexpr float kNear = 0.1f;

// The eye at the origin looking down -z, 60 degrees vertically.
glm::mat4 view_proj() {
    return glm::perspective(glm::radians(60.0f), float(W) / float(H), kNear, 1000.0f) *
           glm::lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::ivec4 rect(glm::vec3 lo, glm::vec3 hi, int margin = 0) {
    return effects::screen_rect_of_box(view_proj(), kNear, lo, hi, W, H, margin);
}

}  // namespace

TEST(ScreenRect, ABoxInFrontGetsItsProjectedBounds) {
    // x, y in [-1, 1] at 10 m: tan(30 deg) * 10 = 5.77 m is half the height.
    const glm::ivec4 r = rect({-1.0f, -1.0f, -10.0f}, {1.0f, 1.0f, -10.0f});
    const float half_h_px = float(H) / 2.0f / (10.0f * std::tan(glm::radians(30.0f)));
    EXPECT_NEAR(r.x, W / 2 - half_h_px, 1.0);
    EXPECT_NEAR(r.z, W / 2 + half_h_px, 1.0);
    EXPECT_NEAR(r.y, H / 2 - half_h_px, 1.0);
    EXPECT_NEAR(r.w, H / 2 + half_h_px, 1.0);
}

TEST(ScreenRect, MarginGrowsTheRectangleAndTheViewportClampsIt) {
    const glm::ivec4 r = rect({-1.0f, -1.0f, -10.0f}, {1.0f, 1.0f, -10.0f});
    const glm::ivec4 m = rect({-1.0f, -1.0f, -10.0f}, {1.0f, 1.0f, -10.0f}, 7);
    EXPECT_EQ(m, r + glm::ivec4(-7, -7, 7, 7));
    EXPECT_EQ(rect({-50.0f, -50.0f, -10.0f}, {50.0f, 50.0f, -10.0f}), glm::ivec4(0, 0, W, H));
}

TEST(ScreenRect, ABoxStraddlingTheEyeCoversOnlyItsFootprintInFront) {
    // From 5 m behind the eye to 5 m in front, wholly to the right of it and below eye
    // level: its part in front of the near plane fills the lower right of the screen.
    const glm::ivec4 r = rect({0.5f, -3.0f, -5.0f}, {3.0f, -0.5f, 5.0f});
    EXPECT_GE(r.x, W / 2) << "the box is right of the eye";
    EXPECT_EQ(r.z, W);
    EXPECT_EQ(r.y, 0);
    EXPECT_LE(r.w, H / 2) << "the box is below eye level";
    EXPECT_LT((r.z - r.x) * (r.w - r.y), W * H / 4 + 1);
}

TEST(ScreenRect, ABoxBehindTheEyeCoversNothing) {
    EXPECT_EQ(rect({-1.0f, -1.0f, 2.0f}, {1.0f, 1.0f, 4.0f}), glm::ivec4(0));
    // Beside the view, in front: nothing either.
    EXPECT_EQ(rect({-100.0f, -1.0f, -4.0f}, {-90.0f, 1.0f, -2.0f}), glm::ivec4(0));
}

TEST(ScreenRect, TheEyeInsideTheBoxSeesItEverywhere) {
    EXPECT_EQ(rect({-1.0f, -1.0f, -1.0f}, {1.0f, 1.0f, 1.0f}), glm::ivec4(0, 0, W, H));
}
