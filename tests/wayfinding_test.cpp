// The wayfinding HUD without GL: which switch prompt shows (and that it agrees with the
// sim's rule), and where the other vehicle's marker goes for a given camera.
#include "game/play/WayfindingHud.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "SimTestLevel.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/world/World.h"

namespace {

using game::SwitchPrompt;
using sim::Vehicle;

constexpr float kW = 1280.0f, kH = 720.0f;

// Looking along -z from 5 m up, as a chase camera behind a car heading that way.
sim::CameraView looking_north() {
    sim::CameraView v;
    v.eye = {0.0f, 5.0f, 10.0f};
    v.target = {0.0f, 1.0f, 0.0f};
    v.fov_y_deg = 60.0f;
    return v;
}

TEST(Wayfinding, PromptNamesWhatEWouldTakeWithinSwitchingReach) {
    const glm::vec3 car{0.0f, 1.0f, 0.0f};
    const float reach = sim::Player::kSwitchDistance_m;
    EXPECT_EQ(game::switch_prompt(Vehicle::Car, car, {10.0f, 0.0f, 5.0f}), SwitchPrompt::TakeBoat);
    EXPECT_EQ(game::switch_prompt(Vehicle::Boat, car, {10.0f, 0.0f, 5.0f}), SwitchPrompt::TakeCar);
    EXPECT_EQ(game::switch_prompt(Vehicle::Car, car, {reach, 0.0f, 0.0f}), SwitchPrompt::TakeBoat);  // inclusive
    EXPECT_EQ(game::switch_prompt(Vehicle::Car, car, {reach + 0.01f, 0.0f, 0.0f}), SwitchPrompt::None);
    EXPECT_EQ(game::switch_prompt(Vehicle::Car, car, {0.0f, 30.0f, 1.0f}), SwitchPrompt::TakeBoat);  // flat distance
    EXPECT_EQ(game::switch_prompt_text(SwitchPrompt::TakeBoat), "E: take the boat");
    EXPECT_EQ(game::switch_prompt_text(SwitchPrompt::TakeCar), "E: take the car");
    EXPECT_EQ(game::switch_prompt_text(SwitchPrompt::None), "");
}

// The prompt shows exactly when pressing E switches.
TEST(Wayfinding, PromptAgreesWithTheSimsSwitch) {
    for (const glm::vec3 spawn : {glm::vec3(36.0f, 1.0f, 30.0f), glm::vec3(0.0f, 1.0f, -12.0f)}) {
        sim::LevelDesc l = make_test_level();
        l.car_spawn.position = spawn;
        sim::World w(l);
        w.step(sim::TickInput{});
        const SwitchPrompt prompt =
            game::switch_prompt(Vehicle::Car, w.get<sim::Car>().position(), w.get<sim::Boat>().position());
        sim::TickInput e;
        e.set(sim::Control::SwitchVehicle, true);
        w.step(e);
        EXPECT_EQ(prompt == SwitchPrompt::TakeBoat, w.get<sim::Player>().vehicle() == Vehicle::Boat)
            << spawn.x << ", " << spawn.z;
    }
}

TEST(Wayfinding, NoMarkerWithinReach) {
    const game::VehicleMarker m =
        game::vehicle_marker(Vehicle::Car, {0.0f, 1.0f, 0.0f}, {5.0f, 0.0f, 0.0f}, looking_north(), kW, kH);
    EXPECT_FALSE(m.shown);
    EXPECT_NEAR(m.distance_m, 5.0f, 1e-5f);
}

TEST(Wayfinding, AVehicleInViewIsMarkedOverItself) {
    const glm::vec3 car{0.0f, 1.0f, 0.0f}, boat{0.0f, 0.0f, -100.0f};  // straight ahead
    const game::VehicleMarker m = game::vehicle_marker(Vehicle::Car, car, boat, looking_north(), kW, kH);
    ASSERT_TRUE(m.shown);
    EXPECT_EQ(m.vehicle, Vehicle::Boat);
    EXPECT_NEAR(m.distance_m, 100.0f, 1e-3f);
    EXPECT_TRUE(m.in_view);
    EXPECT_NEAR(m.position.x, kW / 2, 0.5f);
    EXPECT_GT(m.position.y, 0.0f);
    EXPECT_LT(m.position.y, kH / 2);  // above the centre: the horizon side
    EXPECT_EQ(m.direction, glm::vec2(0.0f, 1.0f));  // pointing down at it

    // From the boat, the car is marked the same way.
    const game::VehicleMarker back = game::vehicle_marker(Vehicle::Boat, boat, car, looking_north(), kW, kH);
    EXPECT_EQ(back.vehicle, Vehicle::Car);
    EXPECT_TRUE(back.in_view);
}

TEST(Wayfinding, AVehicleOutOfViewGetsAnEdgeArrowPointingAtIt) {
    const glm::vec3 car{0.0f, 1.0f, 0.0f};
    const float margin = game::kMarkerEdgeMargin_px;
    // Far to the right, level with the camera's view: the right edge, pointing right.
    game::VehicleMarker m = game::vehicle_marker(Vehicle::Car, car, {400.0f, 0.0f, -20.0f}, looking_north(), kW, kH);
    ASSERT_TRUE(m.shown);
    EXPECT_FALSE(m.in_view);
    EXPECT_NEAR(m.position.x, kW - margin, 0.5f);
    EXPECT_GT(m.direction.x, 0.9f);
    // To the left: the left edge.
    m = game::vehicle_marker(Vehicle::Car, car, {-400.0f, 0.0f, -20.0f}, looking_north(), kW, kH);
    EXPECT_NEAR(m.position.x, margin, 0.5f);
    EXPECT_LT(m.direction.x, -0.9f);
    // Behind the camera: at the bottom edge, pointing down (turn round), not mirrored up.
    m = game::vehicle_marker(Vehicle::Car, car, {0.0f, 0.0f, 200.0f}, looking_north(), kW, kH);
    EXPECT_FALSE(m.in_view);
    EXPECT_NEAR(m.position.y, kH - margin, 0.5f);
    EXPECT_GT(m.direction.y, 0.9f);
    // Behind and to the right: still on the right, not mirrored to the left.
    m = game::vehicle_marker(Vehicle::Car, car, {150.0f, 0.0f, 150.0f}, looking_north(), kW, kH);
    EXPECT_GT(m.direction.x, 0.0f);
    EXPECT_GT(m.position.x, kW / 2);
    // Every edge arrow stays inside the margin.
    for (float angle = 0.0f; angle < 6.3f; angle += 0.1f) {
        const glm::vec3 boat{300.0f * std::cos(angle), 0.0f, 300.0f * std::sin(angle)};
        m = game::vehicle_marker(Vehicle::Car, car, boat, looking_north(), kW, kH);
        EXPECT_GE(m.position.x, margin - 0.5f) << angle;
        EXPECT_LE(m.position.x, kW - margin + 0.5f) << angle;
        EXPECT_GE(m.position.y, margin - 0.5f) << angle;
        EXPECT_LE(m.position.y, kH - margin + 0.5f) << angle;
        EXPECT_NEAR(glm::length(m.direction), 1.0f, 1e-4f) << angle;
    }
}

TEST(Wayfinding, MarkersStayAboveTheBandTheReplayViewersTimelineCovers) {
    const float margin = game::kMarkerEdgeMargin_px, band = 200.0f, floor_y = kH - margin - band;
    // Low in view: marked over itself on a bare screen, where the timeline would hide it
    // an arrow on the band's edge pointing down at it.
    const glm::vec3 car{100.0f, 1.0f, 0.0f}, low{0.0f, -4.0f, 2.0f};
    game::VehicleMarker m = game::vehicle_marker(Vehicle::Car, car, low, looking_north(), kW, kH);
    ASSERT_TRUE(m.in_view);
    EXPECT_GT(m.position.y, floor_y);
    m = game::vehicle_marker(Vehicle::Car, car, low, looking_north(), kW, kH, band);
    ASSERT_TRUE(m.shown);
    EXPECT_FALSE(m.in_view);
    EXPECT_NEAR(m.position.y, floor_y, 0.5f);
    EXPECT_GT(m.direction.y, 0.9f);
    // Behind the camera: on the band's edge, not under it.
    m = game::vehicle_marker(Vehicle::Car, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 200.0f}, looking_north(), kW, kH, band);
    EXPECT_NEAR(m.position.y, floor_y, 0.5f);
    // All round, every arrow above the band and inside the other margins.
    for (float angle = 0.0f; angle < 6.3f; angle += 0.1f) {
        const glm::vec3 boat{300.0f * std::cos(angle), 0.0f, 300.0f * std::sin(angle)};
        m = game::vehicle_marker(Vehicle::Car, {0.0f, 1.0f, 0.0f}, boat, looking_north(), kW, kH, band);
        EXPECT_LE(m.position.y, floor_y + 0.5f) << angle;
        EXPECT_GE(m.position.y, margin - 0.5f) << angle;
        EXPECT_GE(m.position.x, margin - 0.5f) << angle;
        EXPECT_LE(m.position.x, kW - margin + 0.5f) << angle;
    }
}

}  // namespace
