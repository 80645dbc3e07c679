#include "game/play/InputQueue.h"

namespace game {

void InputQueue::press(sim::Control control) {
    const uint16_t bit = uint16_t(control);
    if (bit & sim::kOneShotControls)
        presses_.push_back(control);
    else
        tapped_ |= bit;
}

void InputQueue::set_down(sim::TickInput down) {
    down_ = down.held;
    axes_ = down;
}

sim::TickInput InputQueue::next_tick() {
    uint16_t held = (down_ | tapped_) & ~sim::kOneShotControls;
    tapped_ = 0;
    // A one-shot control stays held while its key is, which gives no new edge; it never
    // rises without a press.
    uint16_t one_shot = last_ & down_ & sim::kOneShotControls;
    if (!presses_.empty()) {
        const uint16_t next = uint16_t(presses_.front());
        if (last_ & next) {
            one_shot &= ~next;  // a tick without it, so that the press makes an edge
        } else {
            one_shot |= next;
            presses_.pop_front();
        }
    }
    last_ = one_shot;
    sim::TickInput in = axes_;
    in.held = uint16_t(held | one_shot);
    return in;
}

void InputQueue::clear() {
    presses_.clear();
    tapped_ = 0;
}

}  // namespace game
