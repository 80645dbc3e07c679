#pragma once
// The ghost's box on the HUD (play --ghost): which replay it is, and the gap to it at
// the latest gate both have passed, as time-trial games show it: "+0.42 s" behind the
// ghost (red), "-0.42 s" ahead of it (green), bright for a few seconds after the gate.
#include <cstdint>
#include <string>
#include <vector>

#include "game/play/GhostRace.h"

namespace game {

// "+0.42 s", "-1.05 s", "0.00 s": a gap of whole ticks in seconds.
std::string gap_text(int64_t ticks);

// The box's lines: the ghost's name (and whether its replay has ended), then the latest
// gap with its course, gate and lap.
std::vector<std::string> ghost_hud_lines(const GhostRace& race);

// The box under the objectives', inside an ImGui frame; `live_tick` the player's world's.
void draw_ghost_hud(const GhostRace& race, uint64_t live_tick);

}  // namespace game
