#include "game/cli/SettingsOption.h"

#include <iostream>

#include "game/cli/QualityOption.h"

namespace game {

PlayerSettings player_settings(const Args& args) {
    PlayerSettings out;
    const std::optional<std::string> path = args.value("--settings");
    out.file = std::make_unique<SettingsFile>(path ? std::filesystem::path(*path) : default_settings_path());
    for (const std::string& problem : out.file->problems())
        std::cerr << "settings: " << out.file->path().string() << ": " << problem << "\n";
    out.settings = out.file->settings();
    if (args.value("--quality")) out.settings.quality = quality_option(args);
    if (args.flag("--fullscreen")) out.settings.window.fullscreen = true;
    if (args.flag("--windowed")) out.settings.window.fullscreen = false;
    return out;
}

}  // namespace game
