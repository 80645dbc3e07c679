#pragma once
// A scripted camera: from its tick on, the frames are seen from where it puts the eye
// instead of the player's camera, until the next shot. Presentation only: the sim never
// reads it, so a replay's hashes do not depend on its shots (docs/REPLAYS.md).
#include <cmath>
#include <cstdint>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace game {

enum class CameraShotKind : uint8_t {
    Follow = 0,  // the player's own camera (the sim's chase or driver's view) again
    Look = 1,    // a fixed eye looking at a fixed point
    Orbit = 2,   // circling a point at a radius and height above it, looking at it
};
inline constexpr uint8_t kCameraShotKinds = 3;

struct CameraShot {
    uint32_t tick = 0;  // in force for the frames of the world after this many ticks on
    CameraShotKind kind = CameraShotKind::Follow;
    glm::vec3 point{0.0f};   // Look: the eye; Orbit: the centre it circles and looks at
    glm::vec3 target{0.0f};  // Look: the point looked at
    float radius_m = 0.0f;   // Orbit: horizontal distance of the eye from the centre
    float height_m = 0.0f;   // Orbit: the eye's height above the centre
    float deg_per_s = 0.0f;  // Orbit: turning rate, positive anticlockwise seen from above
    float start_deg = 0.0f;  // Orbit: where the eye starts, 0 on the centre's +x side
    float fov_deg = 60.0f;   // vertical field of view (Look and Orbit)

    bool operator==(const CameraShot&) const = default;
};

// Bounds a shot must keep, so that any stored shot makes a usable view.
inline constexpr float kMaxCameraCoordinate_m = 100000.0f;
inline constexpr float kMinOrbitRadius_m = 0.1f, kMaxOrbitRadius_m = 10000.0f;
inline constexpr float kMaxOrbitRate_deg_per_s = 3600.0f;
inline constexpr float kMinCameraFov_deg = 5.0f, kMaxCameraFov_deg = 120.0f;
inline constexpr float kMinLookDistance_m = 0.01f;
// The view may not point within about a degree of straight up or down, where the
// world's up no longer says which way the picture's top is.
inline constexpr float kMaxLookSteepness = 0.9998f;  // |dy| / length

// Why `shot` cannot be used, or "" if it can. Shared by the script parser, the replay
// writer and the reader.
inline std::string camera_shot_problem(const CameraShot& s) {
    using std::to_string;
    if (uint8_t(s.kind) >= kCameraShotKinds) return "unknown camera kind " + to_string(int(s.kind));
    const float values[] = {s.point.x,  s.point.y,  s.point.z,   s.target.x,  s.target.y, s.target.z,
                            s.radius_m, s.height_m, s.deg_per_s, s.start_deg, s.fov_deg};
    for (float v : values)
        if (!std::isfinite(v)) return "a camera value is not a finite number";
    if (s.kind == CameraShotKind::Follow) return {};
    if (!(s.fov_deg >= kMinCameraFov_deg && s.fov_deg <= kMaxCameraFov_deg))
        return "the field of view " + to_string(s.fov_deg) + " is outside " + to_string(int(kMinCameraFov_deg)) +
               ".." + to_string(int(kMaxCameraFov_deg)) + " degrees";
    for (const glm::vec3& p : {s.point, s.target})
        if (std::fabs(p.x) > kMaxCameraCoordinate_m || std::fabs(p.y) > kMaxCameraCoordinate_m ||
            std::fabs(p.z) > kMaxCameraCoordinate_m)
            return "a camera position is more than 100 km from the origin";
    if (s.kind == CameraShotKind::Look) {
        const glm::vec3 d = s.target - s.point;
        const float length = glm::length(d);
        if (!(length >= kMinLookDistance_m)) return "the camera's eye and target are the same point";
        if (std::fabs(d.y) > kMaxLookSteepness * length) return "the camera looks straight up or down";
        return {};
    }
    if (!(s.radius_m >= kMinOrbitRadius_m && s.radius_m <= kMaxOrbitRadius_m))
        return "the orbit radius " + to_string(s.radius_m) + " m is outside 0.1..10000 m";
    if (std::fabs(s.height_m) > kMaxOrbitRadius_m) return "the orbit height is more than 10000 m";
    if (std::fabs(s.height_m) > kMaxLookSteepness * std::hypot(s.radius_m, s.height_m))
        return "the orbit looks straight up or down";
    if (std::fabs(s.deg_per_s) > kMaxOrbitRate_deg_per_s)
        return "the orbit turns faster than 3600 degrees a second";
    if (std::fabs(s.start_deg) > 360.0f) return "the orbit's start angle is outside -360..360 degrees";
    return {};
}

}  // namespace game
