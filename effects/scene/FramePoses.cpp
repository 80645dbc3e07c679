#include "effects/scene/FramePoses.h"

#include <cmath>

#include <glm/common.hpp>

#include "sim/objects/ThrownObjects.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"

namespace effects {

namespace {

float lerp_angle(float a, float b, float t) {
    constexpr float kTwoPi = 6.28318530718f;
    float d = std::fmod(b - a, kTwoPi);
    if (d > 0.5f * kTwoPi) d -= kTwoPi;
    if (d < -0.5f * kTwoPi) d += kTwoPi;
    return b - (1.0f - t) * d;
}

sim::Pose lerp_pose(const sim::Pose& a, const sim::Pose& b, float t) {
    sim::Pose p = b;
    p.position = glm::mix(a.position, b.position, t);
    p.heading_rad = lerp_angle(a.heading_rad, b.heading_rad, t);
    p.pitch_rad = lerp_angle(a.pitch_rad, b.pitch_rad, t);
    p.roll_rad = lerp_angle(a.roll_rad, b.roll_rad, t);
    return p;
}

}  // namespace

FramePoses capture_poses(const sim::World& world) {
    FramePoses p;
    if (const auto* rig = world.find<sim::CameraRig>()) p.camera = rig->view();
    if (const auto* car = world.find<sim::Car>()) {
        p.car = car->pose();
        p.car_steer_rad = car->steer_rad();
        p.car_wheel_spin_rad = car->wheel_spin_rad();
        p.car_speed_mps = car->speed_mps();
    }
    if (const auto* player = world.find<sim::Player>()) {
        p.wipers = player->wipers();
        p.boat_steer = player->drive_input(sim::Vehicle::Boat).steer;
    }
    if (const auto* boat = world.find<sim::Boat>()) p.boat = boat->pose();
    if (const auto* objects = world.find<sim::ThrownObjects>())
        for (const sim::ThrownObject& o : objects->objects())
            p.objects.push_back({o.position, o.radius_m, o.sinks(), o.age_ticks});
    p.markers = objective_markers(world);
    return p;
}

FramePoses interpolate(const FramePoses& from, const FramePoses& to, float t) {
    t = glm::clamp(t, 0.0f, 1.0f);
    FramePoses p = to;
    p.camera.eye = glm::mix(from.camera.eye, to.camera.eye, t);
    p.camera.target = glm::mix(from.camera.target, to.camera.target, t);
    p.camera.up = glm::mix(from.camera.up, to.camera.up, t);
    p.camera.fov_y_deg = glm::mix(from.camera.fov_y_deg, to.camera.fov_y_deg, t);
    p.car = lerp_pose(from.car, to.car, t);
    p.car_steer_rad = glm::mix(from.car_steer_rad, to.car_steer_rad, t);
    p.car_wheel_spin_rad = lerp_angle(from.car_wheel_spin_rad, to.car_wheel_spin_rad, t);
    p.car_speed_mps = glm::mix(from.car_speed_mps, to.car_speed_mps, t);
    p.boat = lerp_pose(from.boat, to.boat, t);
    p.boat_steer = glm::mix(from.boat_steer, to.boat_steer, t);
    for (size_t i = 0; i < p.objects.size() && i < from.objects.size(); ++i)
        if (from.objects[i].age_ticks + 1 == to.objects[i].age_ticks)
            p.objects[i].position = glm::mix(from.objects[i].position, to.objects[i].position, t);
    if (from.ghost && to.ghost && from.ghost->vehicle == to.ghost->vehicle)
        p.ghost->pose = lerp_pose(from.ghost->pose, to.ghost->pose, t);
    return p;
}

}  // namespace effects
