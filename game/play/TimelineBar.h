#pragma once
// The replay viewer's timeline (docs/REPLAYS.md, "The viewer"): a bar along the foot of
// the window from tick 0 to the replay's last, the playhead, a mark for each of the
// replay's markers, the time now and in all, the speed and the camera; a click or a drag
// on the bar seeks. The geometry is apart from the drawing, so tests check it without a
// window; the drawing is Dear ImGui's, inside the play loop's UI frame.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "game/replay/ReplayMarkers.h"

namespace game {

// Ticks along a bar from x `left` (tick 0) to x `right` (the last tick), in pixels.
class TimelineGeometry {
public:
    TimelineGeometry(float left, float right, uint64_t ticks);

    float x_of(uint64_t tick) const;
    // The tick nearest `x`, clamped to the bar.
    uint64_t tick_at(float x) const;

private:
    float left_, right_;
    uint64_t ticks_;
};

// "m:ss.ss" of `tick` at the sim's tick rate.
std::string replay_clock(uint64_t tick);

struct TimelineState {
    uint64_t tick = 0, ticks = 0;
    const std::vector<ReplayMarker>* markers = nullptr;
    double speed = 1.0;
    bool paused = false;
    std::string camera;  // the camera's name
    std::string note;    // e.g. the marker just passed, a desync; may be empty
};

struct TimelineDrawn {
    std::optional<uint64_t> seek;  // the tick a click or a drag on the bar asked for
    float covered_px = 0.0f;       // the band at the screen's foot it covers, its margin included
};

// Draws the timeline at the foot of the current ImGui frame.
TimelineDrawn draw_timeline(const TimelineState& state);

}  // namespace game
