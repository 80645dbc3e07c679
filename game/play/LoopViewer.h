#pragma once
// What a replay viewer (ReplayViewer) does inside the play loop: its keys come first, it
// says how many of the replay's ticks each frame plays (the loop steps them through its
// TickDriver) and how far between two ticks to draw, it places the camera and draws its
// timeline, and once it hands over (a take over) the keyboard drives from the tick the
// world is at. The loop knows no more of it than this.
#include <optional>

#include "effects/scene/FramePoses.h"
#include "game/play/Screen.h"

namespace game {

class LoopViewer {
public:
    virtual ~LoopViewer() = default;

    // A key press; true when it was the viewer's.
    virtual bool key(int glfw_key) = 0;
    // Before the frame's ticks: does what the last frame's mouse asked (a seek on the
    // timeline). True when the world (or the playing) changed other than by ticks played
    // since the last call: the loop then draws from the world as it is, not between ticks.
    virtual bool settle() = 0;
    // The replay's ticks due in `dt_s` seconds of real time at the viewer's speed.
    virtual int ticks_due(double dt_s) = 0;
    // How far real time is past the last tick, in ticks [0, 1].
    virtual double alpha() const = 0;
    // Puts the frame's camera where the viewer looks from (`poses` are the drawn ones).
    virtual void view(effects::FramePoses& poses) = 0;
    // Inside the UI's frame: the timeline (unless hidden) and the mouse's camera moves.
    virtual void draw(Screen::Size size) = 0;
    // Whether nothing on screen changes until an event comes (paused, the camera at rest,
    // no seek pending): the loop then idles as when paused, sleeping between events.
    virtual bool still() const = 0;
    virtual bool hud_shown() const = 0;
    // Whether the keyboard drives from now on (a take over).
    virtual bool handed_over() const = 0;
    // The band at the screen's foot its last draw() covered, in pixels (0: none): the
    // HUD's edge arrows stay above it.
    virtual float covered_bottom_px() const = 0;
};

}  // namespace game
