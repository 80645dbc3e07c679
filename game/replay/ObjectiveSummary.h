#pragma once
// The objectives as text: lap times, and the summary `spindrift replay` and
// `spindrift-check` print after a replay's ticks. No GL: spindrift-check has it too.
#include <cstdint>
#include <string>
#include <vector>

#include "sim/objectives/Targets.h"
#include "sim/world/World.h"

namespace game {

// "0:23.45": minutes, seconds and hundredths of `ticks` at 60 ticks a second.
std::string lap_time_text(uint64_t ticks);

// Every course and the targets, one line each, as the replay left them:
// "course quay (car): 1 lap, last 0:23.45, best 0:23.45 (1407 ticks)", "targets hit 2 of 6".
std::vector<std::string> objective_summary_lines(const sim::World& world);

// "targets hit 2 of 6"; the HUD shows it too.
std::string targets_line(const sim::Targets& targets);

}  // namespace game
