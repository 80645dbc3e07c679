#pragma once
// The sound's controls at the end of the F1 panel: mute (M) and the four volumes.
#include "game/audio/LiveSound.h"

namespace game {

void draw_sound_panel(LiveSound& sound);

}  // namespace game
