#pragma once
// What the renderer draws from the sim that moves every tick: the camera, the car (with
// its wheels and cabin instruments), the boat and the thrown objects. Captured after a tick; a frame that
// falls between two ticks draws them where they were in between (render interpolation),
// so motion stays smooth whatever the frame rate. Everything else is drawn as of the
// latest tick.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "effects/scene/ObjectiveMarkers.h"
#include "sim/core/Pose.h"
#include "sim/player/CameraRig.h"
#include "sim/player/Player.h"
#include "sim/world/World.h"

namespace effects {

struct FramePoses {
    sim::CameraView camera;
    sim::Pose car, boat;
    float car_steer_rad = 0.0f, car_wheel_spin_rad = 0.0f, car_speed_mps = 0.0f;
    sim::WiperMode wipers = sim::WiperMode::Off;
    float boat_steer = 0.0f;  // the boat's steering input: its helm wheel turns with it
    struct Object {
        glm::vec3 position{0.0f};
        float radius_m = 0.0f;
        bool sinks = false;
        uint32_t age_ticks = 0;  // tells one object from the next that took its slot
    };
    std::vector<Object> objects;
    std::vector<ObjectiveMarker> markers;  // gates and targets: they change only by the tick
    // A replay's vehicle raced beside the player's (play --ghost), drawn translucent.
    struct Ghost {
        sim::Vehicle vehicle = sim::Vehicle::Car;
        sim::Pose pose;
    };
    std::optional<Ghost> ghost;
};

FramePoses capture_poses(const sim::World& world);

// `to` moved back towards `from` by 1 - t: t = 0 is `from`, t = 1 is `to`. Angles take
// the short way round; an object that was not in `from` (same slot, one tick younger)
// stays where `to` has it.
FramePoses interpolate(const FramePoses& from, const FramePoses& to, float t);

}  // namespace effects
