#include "game/session/TickDriver.h"

namespace game {

sim::TickInput TickDriver::step(sim::TickInput input) {
    const sim::TickInput applied = sim::quantise(input);
    world_->step(applied);
    for (const Listener& l : listeners_) l(*world_, applied);
    return applied;
}

}  // namespace game
