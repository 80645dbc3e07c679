#pragma once
// The car's cabin parts that move with the sim, as tools/make_assets.cpp models them:
// the speedometer's needle, the steering wheel and the wiper stalk on its column; and
// the boat's helm wheel.
#include <glm/vec3.hpp>

#include "sim/player/Player.h"

namespace effects::cabin {

constexpr float kSpeedoFullScaleMps = 200.0f / 3.6f;  // the dial reads 0 to 200 km/h
constexpr float kSteeringRatio = 14.0f;               // wheel turn per front-wheel turn
constexpr float kColumnTiltRad = 0.35f;               // the wheel's top leans this far forward
constexpr float kHelmLockRad = 2.4f;                  // the boat's wheel at full helm
constexpr float kHelmTiltRad = 0.5f;                  // and its top's lean forward

// The needle's turn from straight up, anticlockwise as the driver sees it: 0 km/h at the
// lower left (+135 degrees), full scale at the lower right (-135), reversing reads as speed.
float speedo_needle_rad(float speed_mps);
// The steering wheel's turn, anticlockwise as the driver sees it, for the front wheels'
// angle (positive turns left).
float steering_wheel_rad(float front_wheel_rad);
// The wiper stalk's turn about the column: one notch down per setting past Off.
float wiper_stalk_rad(sim::WiperMode mode);

// The boat's helm wheel's turn, anticlockwise as the helmsman sees it, for the steering
// input (-1 right .. +1 left, sim::DriveInput::steer): the rudder follows the wheel.
float helm_wheel_rad(float steer);

// Axes (vehicle frame, pointing at the driver) the parts turn about.
inline glm::vec3 dial_axis() { return {-1.0f, 0.0f, 0.0f}; }
glm::vec3 column_axis();
glm::vec3 helm_axis();

}  // namespace effects::cabin
