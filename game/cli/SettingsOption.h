#pragma once
// The player's settings for a run in a window: settings.json (or --settings FILE) with
// what the command line says for this run on top (--quality, --fullscreen, --windowed).
#include "game/cli/Args.h"
#include "game/settings/SettingsFile.h"

namespace game {

// Reads the file and reports each problem in it on stderr, one line each.
PlayerSettings player_settings(const Args& args);

}  // namespace game
