#include <cmath>

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

#include "effects/scene/CabinInstruments.h"

namespace {

using namespace effects::cabin;

TEST(CabinInstruments, NeedleRestsAtZeroAndSweepsClockwiseWithSpeed) {
    EXPECT_FLOAT_EQ(speedo_needle_rad(0.0f), glm::radians(135.0f));
    // 100 km/h, half the dial: straight up.
    EXPECT_NEAR(speedo_needle_rad(100.0f / 3.6f), 0.0f, 1e-5f);
    EXPECT_NEAR(speedo_needle_rad(kSpeedoFullScaleMps), glm::radians(-135.0f), 1e-5f);
    float last = speedo_needle_rad(0.0f);
    for (float v = 1.0f; v <= 55.0f; v += 1.0f) {
        float a = speedo_needle_rad(v);
        EXPECT_LT(a, last) << v << " m/s";
        last = a;
    }
}

TEST(CabinInstruments, NeedleStopsAtFullScaleAndReadsReversingAsSpeed) {
    EXPECT_FLOAT_EQ(speedo_needle_rad(200.0f), speedo_needle_rad(kSpeedoFullScaleMps));
    EXPECT_FLOAT_EQ(speedo_needle_rad(-5.0f), speedo_needle_rad(5.0f));
}

TEST(CabinInstruments, SteeringWheelTurnsWithTheFrontWheels) {
    EXPECT_FLOAT_EQ(steering_wheel_rad(0.0f), 0.0f);
    EXPECT_GT(steering_wheel_rad(0.2f), 0.2f);  // left, and further than the road wheels
    EXPECT_LT(steering_wheel_rad(-0.2f), 0.0f);
    EXPECT_FLOAT_EQ(steering_wheel_rad(0.3f), -steering_wheel_rad(-0.3f));
}

TEST(CabinInstruments, WiperStalkMovesOneNotchPerSetting) {
    EXPECT_FLOAT_EQ(wiper_stalk_rad(sim::WiperMode::Off), 0.0f);
    float off = wiper_stalk_rad(sim::WiperMode::Off), inter = wiper_stalk_rad(sim::WiperMode::Intermittent);
    float low = wiper_stalk_rad(sim::WiperMode::Low), high = wiper_stalk_rad(sim::WiperMode::High);
    EXPECT_LT(inter, off);
    EXPECT_NEAR(low - inter, inter - off, 1e-6f);
    EXPECT_NEAR(high - low, inter - off, 1e-6f);
}

TEST(CabinInstruments, ColumnAxisPointsBackAndUpAtTheDriver) {
    glm::vec3 a = column_axis();
    EXPECT_NEAR(a.x * a.x + a.y * a.y + a.z * a.z, 1.0f, 1e-5f);
    EXPECT_LT(a.x, 0.0f);
    EXPECT_GT(a.y, 0.0f);
}

TEST(CabinInstruments, HelmWheelFollowsTheBoatsSteeringToFullHelm) {
    EXPECT_FLOAT_EQ(helm_wheel_rad(0.0f), 0.0f);
    EXPECT_GT(helm_wheel_rad(0.5f), 0.0f);  // left: anticlockwise as the helmsman sees it
    EXPECT_FLOAT_EQ(helm_wheel_rad(-0.5f), -helm_wheel_rad(0.5f));
    EXPECT_FLOAT_EQ(helm_wheel_rad(1.0f), kHelmLockRad);
    EXPECT_GT(kHelmLockRad, 1.5f);  // a boat's wheel turns further than a car's road wheels
    float last = helm_wheel_rad(-1.0f);
    for (float s = -0.9f; s <= 1.0f; s += 0.1f) {
        EXPECT_GT(helm_wheel_rad(s), last) << s;
        last = helm_wheel_rad(s);
    }
    EXPECT_FLOAT_EQ(helm_wheel_rad(3.0f), kHelmLockRad);  // no further than full helm
}

TEST(CabinInstruments, HelmAxisPointsBackAndUpAtTheHelmsman) {
    glm::vec3 a = helm_axis();
    EXPECT_NEAR(a.x * a.x + a.y * a.y + a.z * a.z, 1.0f, 1e-5f);
    EXPECT_LT(a.x, 0.0f);
    EXPECT_GT(a.y, 0.0f);
    EXPECT_FLOAT_EQ(a.z, 0.0f);
}

}  // namespace
