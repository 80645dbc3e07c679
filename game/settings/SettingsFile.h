#pragma once
// settings.json on disk: found under $XDG_CONFIG_HOME/spindrift (~/.config/spindrift),
// read at start, written only when the player changes something, and then atomically
// (a temporary file renamed over it), so a crash never leaves half a file.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "game/settings/Settings.h"

namespace game {

// $XDG_CONFIG_HOME/spindrift/settings.json, or ~/.config/spindrift/settings.json when
// XDG_CONFIG_HOME is unset or not absolute (the XDG rule); empty if HOME is unset too.
std::filesystem::path default_settings_path();

class SettingsFile {
public:
    // Reads `path` if it exists. A file that cannot be read or parsed, or values that
    // are wrong, give one line each in problems() and the defaults in their place.
    explicit SettingsFile(std::filesystem::path path);

    const std::filesystem::path& path() const { return path_; }
    const Settings& settings() const { return settings_; }
    const std::vector<std::string>& problems() const { return problems_; }

    // Keeps `settings` and writes them, unless they are what is kept already (nothing
    // changed: the file stays as it is). Returns false with `error` set when the file
    // could not be written; the settings are kept for this run all the same.
    bool save(const Settings& settings, std::string& error);

private:
    std::filesystem::path path_;
    Settings settings_;
    std::vector<std::string> problems_;
};

// A run's settings: the file's with the command line's changes, and the file.
struct PlayerSettings {
    std::unique_ptr<SettingsFile> file;
    Settings settings;
};

}  // namespace game
