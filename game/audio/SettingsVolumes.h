#pragma once
// The player's four volumes (the settings', which the menu and the F1 panel both edit)
// as the mixer's buses take them.
#include "audio/Mixer.h"
#include "game/settings/Settings.h"

namespace game {

audio::Volumes mixer_volumes(const Settings::Volumes& volume);

}  // namespace game
