#pragma once
// Where the replay viewer looks from (docs/REPLAYS.md, "The viewer"): the recorded view
// (the player's camera, or the script's camera lines), a chase or a driver's view of
// the vehicle in use whatever the player chose, a free fly camera, or an orbit round
// the vehicle. Presentation only: the sim never sees it. No GL: the viewer feeds it the
// keys and the mouse.
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/core/Pose.h"
#include "sim/player/CameraRig.h"

namespace game {

enum class ViewerCameraMode : uint8_t { Recorded, Chase, Driver, FreeFly, Orbit };
inline constexpr int kViewerCameraModes = 5;
const char* viewer_camera_name(ViewerCameraMode mode);

// One frame's camera controls: movement in the camera's frame (x right, y up, z
// forward; -1..1 each), mouse motion in pixels while a button is held, scroll steps.
struct ViewerCameraInput {
    glm::vec3 move{0.0f};
    glm::vec2 look_px{0.0f};
    float zoom_steps = 0.0f;
    bool fast = false;
};

class ViewerCamera {
public:
    ViewerCameraMode mode() const { return mode_; }
    // Free fly starts where the camera was (`from`); orbit round the vehicle, from
    // `from`'s side of it.
    void set_mode(ViewerCameraMode mode, const sim::CameraView& from, glm::vec3 vehicle);
    void next_mode(const sim::CameraView& from, glm::vec3 vehicle);
    // Moves the free fly or orbit camera; the others ignore it.
    void control(const ViewerCameraInput& in, float dt_s);

    // The view for a frame: `recorded` as the replay shows it, `vehicle` the pose of the
    // vehicle in use (drawn), `in_car` which it is.
    sim::CameraView view(const sim::CameraView& recorded, const sim::Pose& vehicle, bool in_car) const;

private:
    ViewerCameraMode mode_ = ViewerCameraMode::Recorded;
    // Free fly: where it is and where it faces (radians; yaw 0 looks along +x).
    glm::vec3 eye_{0.0f, 5.0f, 0.0f};
    float yaw_ = 0.0f, pitch_ = 0.0f;
    // Orbit: round the vehicle, azimuth and elevation (radians), distance.
    float azimuth_ = 0.0f, elevation_ = 0.35f, distance_m_ = 10.0f;
    sim::CameraRigParams rig_;
};

}  // namespace game
