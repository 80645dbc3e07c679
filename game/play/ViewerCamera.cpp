#include "game/play/ViewerCamera.h"

#include <algorithm>
#include <cmath>

namespace game {

namespace {

constexpr float kLookRadPerPx = 0.005f;
constexpr float kFlySpeed_mps = 12.0f;
constexpr float kFastFactor = 4.0f;
constexpr float kMaxPitch = 1.45f;  // short of straight up or down (the view needs an up)
// An eye this close to the vehicle (flat) is aboard: an orbit from there would look straight down.
constexpr float kOrbitFromAboard_m = 3.0f;

glm::vec3 direction(float yaw, float pitch) {
    return {std::cos(pitch) * std::cos(yaw), std::sin(pitch), -std::cos(pitch) * std::sin(yaw)};
}

}  // namespace

const char* viewer_camera_name(ViewerCameraMode mode) {
    switch (mode) {
        case ViewerCameraMode::Recorded: return "recorded";
        case ViewerCameraMode::Chase: return "chase";
        case ViewerCameraMode::Driver: return "driver";
        case ViewerCameraMode::FreeFly: return "free fly";
        case ViewerCameraMode::Orbit: return "orbit";
    }
    return "?";
}

void ViewerCamera::set_mode(ViewerCameraMode mode, const sim::CameraView& from, glm::vec3 vehicle) {
    mode_ = mode;
    const glm::vec3 d = from.target - from.eye;
    const float len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (mode == ViewerCameraMode::FreeFly) {
        eye_ = from.eye;
        yaw_ = std::atan2(-d.z, d.x);
        pitch_ = len > 0.0f ? std::clamp(std::asin(d.y / len), -kMaxPitch, kMaxPitch) : 0.0f;
    } else if (mode == ViewerCameraMode::Orbit) {
        const glm::vec3 r = from.eye - vehicle;
        const float flat = std::sqrt(r.x * r.x + r.z * r.z);
        if (flat < kOrbitFromAboard_m) {
            // From aboard (the driver's view): behind the vehicle along the view, a little above.
            azimuth_ = std::atan2(d.z, -d.x);
            elevation_ = 0.35f;
            distance_m_ = 10.0f;
            return;
        }
        azimuth_ = std::atan2(-r.z, r.x);
        elevation_ = std::clamp(std::atan2(r.y, flat), 0.05f, kMaxPitch);
        distance_m_ = std::clamp(std::sqrt(flat * flat + r.y * r.y), 3.0f, 60.0f);
    }
}

void ViewerCamera::next_mode(const sim::CameraView& from, glm::vec3 vehicle) {
    set_mode(static_cast<ViewerCameraMode>((int(mode_) + 1) % kViewerCameraModes), from, vehicle);
}

void ViewerCamera::control(const ViewerCameraInput& in, float dt_s) {
    if (mode_ == ViewerCameraMode::FreeFly) {
        yaw_ -= in.look_px.x * kLookRadPerPx;
        pitch_ = std::clamp(pitch_ - in.look_px.y * kLookRadPerPx, -kMaxPitch, kMaxPitch);
        const glm::vec3 forward = direction(yaw_, pitch_);
        const glm::vec3 right{std::sin(yaw_), 0.0f, std::cos(yaw_)};
        const float speed = kFlySpeed_mps * (in.fast ? kFastFactor : 1.0f) * dt_s;
        eye_ += (forward * in.move.z + right * in.move.x + glm::vec3(0.0f, in.move.y, 0.0f)) * speed;
    } else if (mode_ == ViewerCameraMode::Orbit) {
        azimuth_ -= in.look_px.x * kLookRadPerPx + in.move.x * 1.5f * dt_s;
        elevation_ = std::clamp(elevation_ + in.look_px.y * kLookRadPerPx + in.move.y * 1.0f * dt_s, 0.05f, kMaxPitch);
        distance_m_ = std::clamp(distance_m_ * std::pow(0.9f, in.zoom_steps) * (1.0f - in.move.z * dt_s), 3.0f, 60.0f);
    }
}

sim::CameraView ViewerCamera::view(const sim::CameraView& recorded, const sim::Pose& vehicle, bool in_car) const {
    sim::CameraView v;
    switch (mode_) {
        case ViewerCameraMode::Recorded: return recorded;
        case ViewerCameraMode::Driver: return sim::CameraRig::driver_view(vehicle, in_car, rig_.driver_fov_deg);
        case ViewerCameraMode::Chase: {
            // The rig's chase placement without its smoothing (which would need the past).
            const glm::vec3 fwd = vehicle.forward_flat();
            v.eye = vehicle.position - fwd * rig_.chase_distance_m + glm::vec3(0.0f, rig_.chase_height_m, 0.0f);
            v.target = vehicle.position + fwd * rig_.chase_look_ahead_m + glm::vec3(0.0f, 1.0f, 0.0f);
            v.fov_y_deg = rig_.chase_fov_deg;
            return v;
        }
        case ViewerCameraMode::FreeFly:
            v.eye = eye_;
            v.target = eye_ + direction(yaw_, pitch_);
            v.fov_y_deg = rig_.chase_fov_deg;
            return v;
        case ViewerCameraMode::Orbit: {
            const glm::vec3 centre = vehicle.position + glm::vec3(0.0f, 1.0f, 0.0f);
            v.eye = centre + direction(azimuth_, elevation_) * distance_m_;
            v.target = centre;
            v.fov_y_deg = rig_.chase_fov_deg;
            return v;
        }
    }
    return recorded;
}

}  // namespace game
