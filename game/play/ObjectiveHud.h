#pragma once
// The objectives on screen and in a replay's summary: the lap timer of the course for the
// vehicle the player is in (running lap, last and best, next gate) and the targets hit.
#include <cstdint>
#include <string>
#include <vector>

#include "sim/world/World.h"

namespace game {

// "0:23.45": minutes, seconds and hundredths of `ticks` at 60 ticks a second.
std::string lap_time_text(uint64_t ticks);

// The HUD's objective lines for the vehicle the player is in; empty for a world without
// objectives.
std::vector<std::string> objective_hud_lines(const sim::World& world);

// Every course and the targets, one line each, as `replay` prints them after its ticks:
// "course quay (car): 1 lap, last 0:23.45, best 0:23.45 (1407 ticks)".
std::vector<std::string> objective_summary_lines(const sim::World& world);

// The HUD's objective box, at the top of the screen's middle, inside an ImGui frame.
void draw_objective_hud(const sim::World& world);

}  // namespace game
