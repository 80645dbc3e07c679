#include "effects/scene/CabinInstruments.h"

#include <algorithm>
#include <cmath>

#include <glm/trigonometric.hpp>

namespace effects::cabin {

float speedo_needle_rad(float speed_mps) {
    float reading = std::clamp(std::fabs(speed_mps) / kSpeedoFullScaleMps, 0.0f, 1.0f);
    return glm::radians(135.0f - 270.0f * reading);
}

float steering_wheel_rad(float front_wheel_rad) { return front_wheel_rad * kSteeringRatio; }

float wiper_stalk_rad(sim::WiperMode mode) { return -0.14f * float(static_cast<int>(mode)); }

float helm_wheel_rad(float steer) { return std::clamp(steer, -1.0f, 1.0f) * kHelmLockRad; }

glm::vec3 column_axis() { return {-std::cos(kColumnTiltRad), std::sin(kColumnTiltRad), 0.0f}; }

glm::vec3 helm_axis() { return {-std::cos(kHelmTiltRad), std::sin(kHelmTiltRad), 0.0f}; }

}  // namespace effects::cabin
