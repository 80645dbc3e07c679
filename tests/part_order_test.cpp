// The order the opaque pass draws a vehicle's parts in (effects::nearest_first): nearest
// the eye first, the parts whose box holds the eye last.
#include <vector>

#include <gtest/gtest.h>

#include "effects/scene/GpuModel.h"

namespace {

using effects::PartBox;

TEST(PartOrder, NearestFirstAndTheBoxesHoldingTheEyeLast) {
    const std::vector<PartBox> boxes = {
        {{-2, -1, -3}, {2, 1, 3}},          // 0: the body, holding the eye
        {{0, 0, 5}, {1, 1, 6}},             // 1: 5 m ahead
        {{0, 0, 1}, {1, 0.5f, 1.5f}},       // 2: 1 m ahead (the dashboard)
        {{-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}},  // 3: also around the eye
        {{3, 0, 0}, {4, 1, 1}},             // 4: 3 m to the side
    };
    const std::vector<size_t> order = effects::nearest_first(boxes, {0.0f, 0.0f, 0.0f});
    EXPECT_EQ(order, (std::vector<size_t>{2, 4, 1, 0, 3}));
}

TEST(PartOrder, EqualDistancesKeepTheModelsOrder) {
    const std::vector<PartBox> boxes = {{{1, 0, 0}, {2, 1, 1}}, {{-2, 0, 0}, {-1, 1, 1}}, {{0, 0, 1}, {1, 1, 2}}};
    EXPECT_EQ(effects::nearest_first(boxes, {0.0f, 0.0f, 0.0f}), (std::vector<size_t>{0, 1, 2}));
}

}  // namespace
