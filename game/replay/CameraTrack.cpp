#include "game/replay/CameraTrack.h"

#include <algorithm>
#include <cmath>

namespace game {

CameraTrack::CameraTrack(std::vector<CameraShot> shots, uint32_t tick_rate_hz)
    : shots_(std::move(shots)), tick_rate_hz_(std::max<uint32_t>(tick_rate_hz, 1)) {}

int CameraTrack::shot_at(uint64_t tick) const {
    const auto after = std::upper_bound(shots_.begin(), shots_.end(), tick,
                                        [](uint64_t t, const CameraShot& s) { return t < s.tick; });
    return int(after - shots_.begin()) - 1;
}

sim::CameraView CameraTrack::view_at(uint64_t tick, const sim::CameraView& player) const {
    const int i = shot_at(tick);
    if (i < 0 || shots_[size_t(i)].kind == CameraShotKind::Follow) return player;
    const CameraShot& shot = shots_[size_t(i)];
    return shot_view(shot, tick - shot.tick, tick_rate_hz_);
}

sim::CameraView shot_view(const CameraShot& shot, uint64_t ticks_in, uint32_t tick_rate_hz) {
    sim::CameraView v;
    v.fov_y_deg = shot.fov_deg;
    v.up = {0.0f, 1.0f, 0.0f};
    if (shot.kind == CameraShotKind::Look) {
        v.eye = shot.point;
        v.target = shot.target;
        return v;
    }
    // Double precision: an orbit hours long still turns smoothly.
    constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
    const double seconds = double(ticks_in) / double(std::max<uint32_t>(tick_rate_hz, 1));
    const double angle = (double(shot.start_deg) + double(shot.deg_per_s) * seconds) * kDegToRad;
    // Anticlockwise seen from above (+y): from +x towards -z.
    v.eye = shot.point + glm::vec3(float(double(shot.radius_m) * std::cos(angle)), shot.height_m,
                                   float(-double(shot.radius_m) * std::sin(angle)));
    v.target = shot.point;
    return v;
}

}  // namespace game
