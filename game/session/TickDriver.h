#pragma once
// The one place a session steps its world: each tick's input is quantised, the world
// steps, and every listener is told in the order it was added (the recorder, the
// replay checker, the sound). play, replay (in a window and headless) and timedemo all
// drive their world through one.
#include <functional>
#include <vector>

#include "sim/world/World.h"

namespace game {

class TickDriver {
public:
    using Listener = std::function<void(const sim::World&, sim::TickInput applied)>;

    explicit TickDriver(sim::World& world) : world_(&world) {}
    // The course started again in a new world (the menu's Restart): step that one.
    void restart(sim::World& world) { world_ = &world; }
    void listen(Listener listener) { listeners_.push_back(std::move(listener)); }
    // Steps one tick and tells every listener; returns the input as applied.
    sim::TickInput step(sim::TickInput input);
    const sim::World& world() const { return *world_; }

private:
    sim::World* world_;
    std::vector<Listener> listeners_;
};

}  // namespace game
