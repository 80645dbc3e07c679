#include "sim/player/Player.h"

#include <algorithm>

#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/world/World.h"

namespace sim {

Player::Player(float rain_intensity) : rain_intensity_(std::clamp(rain_intensity, 0.0f, 1.0f)) {}

void Player::connect(const SubsystemLinks& links) {
    car_ = &links.need<Car>();
    boat_ = &links.need<Boat>();
}

void Player::step(StepContext& ctx) {
    const TickInput& in = ctx.input;
    controls_.throttle = throttle_amount(in);
    controls_.brake = brake_amount(in);
    controls_.steer = steer_amount(in);

    if (ctx.pressed(Control::SwitchVehicle)) {
        glm::vec3 car = car_->position();
        glm::vec3 boat = boat_->position();
        glm::vec2 d(car.x - boat.x, car.z - boat.z);
        if (d.x * d.x + d.y * d.y <= kSwitchDistance_m * kSwitchDistance_m)
            vehicle_ = vehicle_ == Vehicle::Car ? Vehicle::Boat : Vehicle::Car;
    }
    if (ctx.pressed(Control::Camera)) view_ = view_ == ViewMode::Chase ? ViewMode::Driver : ViewMode::Chase;
    if (ctx.pressed(Control::Wipers)) wipers_ = static_cast<WiperMode>((uint8_t(wipers_) + 1) % 4);
    if (ctx.pressed(Control::RainUp)) rain_intensity_ = std::min(1.0f, rain_intensity_ + kRainStep);
    if (ctx.pressed(Control::RainDown)) rain_intensity_ = std::max(0.0f, rain_intensity_ - kRainStep);
    throw_heavy_ = ctx.pressed(Control::ThrowHeavy);
    throw_light_ = ctx.pressed(Control::ThrowLight);
    fire_ = ctx.pressed(Control::Fire);
    reset_ = ctx.pressed(Control::Reset);
}

DriveInput Player::drive_input(Vehicle v) const {
    if (v == vehicle_) return controls_;
    return DriveInput{0.0f, 1.0f, 0.0f, true};
}


}  // namespace sim
