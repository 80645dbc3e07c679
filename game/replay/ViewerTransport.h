#pragma once
// The replay viewer's playback controls (docs/REPLAYS.md, "The viewer"): pause, speeds
// from 0.1x to 8x, a tick forward or back, jumps by seconds and to the next or previous
// marker, a seek anywhere; it turns the real time of each frame into ticks at the chosen
// speed. The world moves only through the seeker, so every tick is the replay's. No GL:
// the window's keys call it, and the tests drive it frame by frame.
#include <array>
#include <cstdint>

#include "game/replay/ReplayMarkers.h"
#include "game/replay/ReplaySeeker.h"

namespace game {

class ViewerTransport {
public:
    static constexpr std::array<double, 7> kSpeeds{0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0};
    // At most this many ticks a frame: a slow frame at 8x does not snowball.
    static constexpr int kMaxTicksPerFrame = 32;

    ViewerTransport(ReplaySeeker& seeker, const ReplayMarkers& markers) : seeker_(seeker), markers_(markers) {}

    bool paused() const { return paused_; }
    void toggle_pause();
    double speed() const { return kSpeeds[speed_index_]; }
    void faster();
    void slower();

    // Each pauses: single ticks and jumps are looked at, not played through.
    void step_forward();
    void step_back();
    void jump_seconds(double seconds);
    void next_marker();
    void previous_marker();
    void seek_to(uint64_t tick);

    // One frame of `dt_s` real seconds: the ticks due at the speed (none while paused,
    // never past the replay's end, where it pauses), for the caller to step (the viewer
    // steps them through its TickDriver, which tells the seeker).
    int ticks_due(double dt_s);
    // ticks_due, stepped through the seeker. Returns the ticks stepped.
    int advance(double dt_s);
    // How far real time is past the last tick, in ticks [0, 1): for drawing between ticks.
    double alpha() const { return owed_; }
    // Whether the last call moved the world other than one tick on (a seek): the viewer
    // then takes its previous poses afresh.
    bool jumped() const { return jumped_; }

private:
    void go_to(uint64_t tick);

    ReplaySeeker& seeker_;
    const ReplayMarkers& markers_;
    bool paused_ = false;
    size_t speed_index_ = 3;  // 1x
    double owed_ = 0.0;       // ticks of real time not yet played
    bool jumped_ = false;
};

}  // namespace game
