#pragma once
// The sound's controls at the end of the F1 panel: mute (M) and the four volumes, which
// are the player's settings (the caller applies and saves a change, as the menu's).
#include "game/audio/LiveSound.h"
#include "game/settings/Settings.h"

namespace game {

void draw_sound_panel(LiveSound& sound, Settings::Volumes& volume);

}  // namespace game
