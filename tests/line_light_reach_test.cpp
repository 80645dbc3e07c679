// What the opaque pass draws with the beams' line-light sum: a box within reach of a
// segment is kept, one beyond it left out, whatever the segment's direction.
#include <gtest/gtest.h>

#include "effects/scene/SceneLighting.h"

namespace {

effects::LineLight beam(glm::vec3 start, glm::vec3 end, float reach_m) {
    effects::LineLight l;
    l.start = start;
    l.end = end;
    l.reach_m = reach_m;
    return l;
}

}  // namespace

TEST(LineLightReach, ABoxNearTheSegmentIsReachedAndOneBeyondItsReachIsNot) {
    const effects::LineLight l = beam({0, 1, 0}, {10, 1, 0}, 9.0f);
    // Beside the middle of the beam, 8 m off: within reach.
    EXPECT_TRUE(effects::line_light_reaches(l, {4, 0, 8}, {6, 1, 9}));
    // 10 m off the side: beyond it.
    EXPECT_FALSE(effects::line_light_reaches(l, {4, 0, 10}, {6, 1, 12}));
    // Past the head along the beam: 8.5 m is within, 9.5 m is not.
    EXPECT_TRUE(effects::line_light_reaches(l, {18.5f, 0, -1}, {20, 2, 1}));
    EXPECT_FALSE(effects::line_light_reaches(l, {19.5f, 0, -1}, {21, 2, 1}));
    // A box the segment passes through.
    EXPECT_TRUE(effects::line_light_reaches(l, {2, 0, -1}, {3, 2, 1}));
}

TEST(LineLightReach, ADiagonalBeamAndAPointLikeOne) {
    // Rising diagonally: a box above its far end is reached, one behind its start not.
    const effects::LineLight diagonal = beam({0, 0, 0}, {10, 10, 10}, 2.0f);
    EXPECT_TRUE(effects::line_light_reaches(diagonal, {11, 11, 11}, {12, 12, 12}));
    EXPECT_FALSE(effects::line_light_reaches(diagonal, {-5, -5, -5}, {-3, -3, -3}));
    // A segment of zero length is a point light with the same reach.
    const effects::LineLight point = beam({5, 5, 5}, {5, 5, 5}, 1.0f);
    EXPECT_TRUE(effects::line_light_reaches(point, {5.5f, 5.5f, 5.5f}, {7, 7, 7}));
    EXPECT_FALSE(effects::line_light_reaches(point, {6.5f, 0, 0}, {7, 10, 10}));
}
