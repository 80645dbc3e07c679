#pragma once
// Tick inputs for sim tests: the controls held this tick, and a run of ticks with them.
#include <initializer_list>

#include "sim/core/TickInput.h"
#include "sim/world/World.h"

inline sim::TickInput held(std::initializer_list<sim::Control> controls) {
    sim::TickInput in;
    for (sim::Control c : controls) in.set(c, true);
    return in;
}

inline void run(sim::World& w, int ticks, sim::TickInput in) {
    for (int i = 0; i < ticks; ++i) w.step(in);
}
