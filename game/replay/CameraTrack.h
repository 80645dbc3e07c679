#pragma once
// A replay's scripted cameras over time: which shot is in force at a tick and the view
// it gives. Every command that draws a replay's frames (replay, timedemo, a replay in a
// window) puts the camera where the track says, so the replay file alone reproduces them.
#include <cstdint>
#include <span>
#include <vector>

#include "game/replay/CameraShot.h"
#include "sim/player/CameraRig.h"

namespace game {

class CameraTrack {
public:
    CameraTrack() = default;  // no shots: always the player's camera
    // `shots` in ascending tick order, each valid (camera_shot_problem), as a replay header holds them.
    CameraTrack(std::vector<CameraShot> shots, uint32_t tick_rate_hz);

    // Index of the shot in force for the frame of the world after `tick` ticks; -1 before the first.
    int shot_at(uint64_t tick) const;
    // The view for that frame: the shot's, or `player` (the sim's camera) under a follow
    // shot or before any.
    sim::CameraView view_at(uint64_t tick, const sim::CameraView& player) const;
    // Whether the frames of ticks `from` and `to` are seen through different shots: the
    // camera jumps there, so a frame between them must not blend the two views.
    bool cuts_between(uint64_t from, uint64_t to) const { return shot_at(from) != shot_at(to); }

    bool empty() const { return shots_.empty(); }

private:
    std::vector<CameraShot> shots_;
    uint32_t tick_rate_hz_ = 60;
};

// The view a Look or Orbit shot gives `ticks_in` ticks after its own tick.
sim::CameraView shot_view(const CameraShot& shot, uint64_t ticks_in, uint32_t tick_rate_hz);

}  // namespace game
