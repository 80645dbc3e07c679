// Render interpolation: the poses a frame between two ticks draws.
#include <gtest/gtest.h>

#include <cmath>

#include "SimTestLevel.h"
#include "effects/scene/FramePoses.h"
#include "sim/vehicle/Car.h"
#include "sim/world/World.h"

namespace {

effects::FramePoses poses_at(glm::vec3 car, float heading, glm::vec3 eye) {
    effects::FramePoses p;
    p.car.position = car;
    p.car.heading_rad = heading;
    p.camera.eye = eye;
    p.camera.target = eye + glm::vec3(0.0f, 0.0f, -1.0f);
    return p;
}

}  // namespace

TEST(FramePoses, EndsAreTheTwoTicksAndTheMiddleIsBetween) {
    const auto a = poses_at({0, 0, 0}, 0.0f, {0, 2, 5});
    const auto b = poses_at({1, 0, 0}, 0.2f, {1, 2, 5});
    EXPECT_EQ(effects::interpolate(a, b, 0.0f).car.position, a.car.position);
    EXPECT_EQ(effects::interpolate(a, b, 1.0f).car.position, b.car.position);
    const auto m = effects::interpolate(a, b, 0.25f);
    EXPECT_FLOAT_EQ(m.car.position.x, 0.25f);
    EXPECT_FLOAT_EQ(m.car.heading_rad, 0.05f);
    EXPECT_FLOAT_EQ(m.camera.eye.x, 0.25f);
    EXPECT_FLOAT_EQ(m.camera.target.x, 0.25f);
}

TEST(FramePoses, TheBoatsHelmTurnsSmoothlyBetweenTicks) {
    auto a = poses_at({0, 0, 0}, 0.0f, {0, 2, 5});
    auto b = a;
    b.boat_steer = 1.0f;
    EXPECT_FLOAT_EQ(effects::interpolate(a, b, 0.25f).boat_steer, 0.25f);
    EXPECT_FLOAT_EQ(effects::interpolate(a, b, 1.0f).boat_steer, 1.0f);
}

TEST(FramePoses, HeadingsTakeTheShortWayRound) {
    const float pi = 3.14159265f;
    const auto a = poses_at({0, 0, 0}, pi - 0.1f, {0, 2, 5});
    const auto b = poses_at({0, 0, 0}, -pi + 0.1f, {0, 2, 5});
    const float mid = effects::interpolate(a, b, 0.5f).car.heading_rad;
    EXPECT_NEAR(std::cos(mid), -1.0f, 1e-4f) << "half way between 179 and -179 degrees is 180, not 0";
}

TEST(FramePoses, AnObjectNewInItsSlotIsNotDrawnBetweenTwoDifferentObjects) {
    auto a = poses_at({0, 0, 0}, 0.0f, {0, 2, 5});
    auto b = a;
    a.objects = {{{0, 1, 0}, 0.2f, true, 10}, {{5, 1, 0}, 0.2f, true, 30}};
    b.objects = {{{0, 2, 0}, 0.2f, true, 11}, {{9, 9, 9}, 0.3f, false, 0}};  // slot 1: a new throw
    const auto m = effects::interpolate(a, b, 0.5f);
    EXPECT_FLOAT_EQ(m.objects[0].position.y, 1.5f);
    EXPECT_EQ(m.objects[1].position, glm::vec3(9, 9, 9));
}

TEST(FramePoses, CapturedFromTheWorldAsItStands) {
    sim::World world(make_test_level());
    sim::TickInput throttle;
    throttle.held = static_cast<uint16_t>(sim::Control::Throttle);
    for (int i = 0; i < 30; ++i) world.step(throttle);
    const effects::FramePoses p = effects::capture_poses(world);
    EXPECT_EQ(p.car.position, world.get<sim::Car>().pose().position);
    EXPECT_EQ(p.car_wheel_spin_rad, world.get<sim::Car>().wheel_spin_rad());
    EXPECT_EQ(p.camera.eye, world.get<sim::CameraRig>().view().eye);
}
