#pragma once
// Key presses between two frames turned into per-tick inputs, so that every press
// reaches the sim however few ticks a frame runs.
#include <cstdint>
#include <deque>

#include "sim/core/TickInput.h"

namespace game {

// One-shot controls (sim::kOneShotControls: wipers, camera, fire, ...) act on the tick
// their bit rises, so each press gets its own rising edge: a tick with the control held,
// then at least one without it before the next press of it. Presses rise one a tick in
// the order they were made; those a frame has no ticks left for wait for the next
// frame's. Held controls (throttle, brake, steering) follow the keys, and a tap that
// began and ended between two ticks still holds its control for one tick. The analog
// axes follow the gamepad as it was last read.
class InputQueue {
public:
    // A key went down (not an auto-repeat), in the order the keys went down.
    void press(sim::Control control);
    // The controls whose keys are down now, and where the analog axes (a gamepad) are.
    void set_down(sim::TickInput down);
    // The input for the next tick.
    sim::TickInput next_tick();
    // Presses not yet given a tick.
    size_t waiting() const { return presses_.size(); }
    // Forgets waiting presses and taps (the game was paused, a text field took the keys).
    void clear();

private:
    std::deque<sim::Control> presses_;
    uint16_t down_ = 0;
    sim::TickInput axes_;  // its throttle, brake and steer go to every tick as they are
    uint16_t tapped_ = 0;  // held controls pressed since the last tick
    uint16_t last_ = 0;    // one-shot controls held on the last tick
};

}  // namespace game
