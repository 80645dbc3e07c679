#pragma once
// The objectives on screen: the lap timer of the course for the
// vehicle the player is in (running lap, last and best, next gate) and the targets hit.
// A replay's summary is game/replay/ObjectiveSummary.h.
#include <cstdint>
#include <string>
#include <vector>

#include "game/replay/ObjectiveSummary.h"
#include "sim/world/World.h"

namespace game {

// The HUD's objective lines for the vehicle the player is in; empty for a world without
// objectives.
std::vector<std::string> objective_hud_lines(const sim::World& world);

// The HUD's objective box, at the top of the screen's middle, inside an ImGui frame.
void draw_objective_hud(const sim::World& world);

// Begins an ImGui window for a HUD box centred at the top of the screen, `y` pixels
// down: no decoration, no input, sized to its text. End it with ImGui::End() whatever
// this returns.
bool begin_top_hud_box(const char* name, float y);

}  // namespace game
