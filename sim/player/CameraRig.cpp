#include "sim/player/CameraRig.h"

#include <algorithm>
#include <cmath>

#include "sim/core/DetMath.h"
#include "sim/player/Player.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/world/Terrain.h"
#include "sim/world/World.h"

namespace sim {

namespace {
constexpr float kMovingBackwards_mps = 0.5f;
}  // namespace

CameraRig::CameraRig(CameraRigParams params) : p_(params) {}

void CameraRig::connect(const SubsystemLinks& links) {
    player_ = &links.need<Player>();
    car_ = &links.need<Car>();
    boat_ = &links.need<Boat>();
}

void CameraRig::step(StepContext& ctx) {
    const Player& player = *player_;
    bool in_car = player.vehicle() == Vehicle::Car;
    const Pose& pose = in_car ? car_->pose() : boat_->pose();
    float speed = in_car ? car_->speed_mps() : boat_->speed_mps();

    // Reversing for a moment swings the chase camera round to look the way the vehicle
    // goes; driving forwards again swings it back.
    if (speed < -kMovingBackwards_mps) reversing_s_ += ctx.dt;
    else reversing_s_ = 0.0f;
    if (reversing_s_ > p_.reverse_look_delay_s) looking_back_ = true;
    if (speed > kMovingBackwards_mps) looking_back_ = false;
    swing_ = std::clamp(swing_ + (looking_back_ ? 1.0f : -1.0f) * ctx.dt / p_.reverse_swing_s, 0.0f, 1.0f);
    // Eased in and out, round the vehicle's right side.
    float angle = 3.14159265f * swing_ * swing_ * (3.0f - 2.0f * swing_);
    float sa, ca;
    det::sincos(angle, sa, ca);
    glm::vec3 fwd = pose.forward_flat() * ca + pose.right_flat() * sa;

    float dist = p_.chase_distance_m + p_.speed_pullback * std::fabs(speed);
    glm::vec3 want_eye = pose.position - fwd * dist + glm::vec3(0.0f, p_.chase_height_m, 0.0f);
    glm::vec3 want_target = pose.position + fwd * p_.chase_look_ahead_m + glm::vec3(0.0f, 1.0f, 0.0f);
    if (!initialised_) {
        chase_eye_ = want_eye;
        chase_target_ = want_target;
        initialised_ = true;
    }
    chase_eye_ += (want_eye - chase_eye_) * p_.follow_rate;
    chase_target_ += (want_target - chase_target_) * (2.0f * p_.follow_rate);
    const Terrain& terrain = ctx.world.terrain();
    float floor = std::max(terrain.ground_height({chase_eye_.x, chase_eye_.z}),
                           ctx.world.sea().height_at({chase_eye_.x, chase_eye_.z})) + 0.6f;
    chase_eye_.y = std::max(chase_eye_.y, floor);

    if (player.view() == ViewMode::Driver) {
        glm::mat4 m = pose.matrix();
        // The driver's eyes: behind the windshield, above the seat, a hand below the roof
        // lining so that the glass, not the roof, fills the view.
        glm::vec3 seat = in_car ? glm::vec3(-0.45f, 1.2f, 0.0f) : glm::vec3(-0.6f, 1.9f, 0.0f);
        glm::vec3 look = seat + glm::vec3(10.0f, in_car ? -0.2f : -0.6f, 0.0f);
        view_.eye = glm::vec3(m * glm::vec4(seat, 1.0f));
        view_.target = glm::vec3(m * glm::vec4(look, 1.0f));
        view_.up = glm::vec3(m * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
        view_.fov_y_deg = p_.driver_fov_deg;
    } else {
        view_.eye = chase_eye_;
        view_.target = chase_target_;
        view_.up = {0.0f, 1.0f, 0.0f};
        view_.fov_y_deg = p_.chase_fov_deg;
    }
}


}  // namespace sim
