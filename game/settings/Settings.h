#pragma once
// What the player sets once and finds again at the next start: the settings file's
// contents (settings.json, SettingsFile), as JSON and back.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "game/play/QualityChoice.h"
#include "game/settings/KeyBindings.h"
#include "sim/player/Player.h"

namespace game {

struct Settings {
    // The file format's version: a file with a higher one is from a newer Spindrift.
    static constexpr int kVersion = 1;

    QualityChoice quality = QualityChoice::Auto;
    // Auto quality's render scale range (the ResolutionController's).
    float auto_min_scale = 0.35f;
    float auto_max_scale = 1.0f;

    struct WindowPlacement {
        int width = 1280, height = 720;  // the windowed size (kept while fullscreen)
        std::optional<int> x, y;         // none: where the window manager puts it
        bool fullscreen = false;
        bool operator==(const WindowPlacement&) const = default;
    } window;
    bool vsync = true;
    bool fxaa = false;  // off in every preset (its cost on llvmpipe); F3 or the menu turns it on

    // 0..1 each; the sound's mixer reads them.
    struct Volumes {
        float master = 0.8f, engine = 0.8f, effects = 0.8f, ambience = 0.6f;
        bool operator==(const Volumes&) const = default;
    } volume;

    sim::ViewMode camera = sim::ViewMode::Chase;  // the view a course starts in
    sim::WiperMode wipers = sim::WiperMode::Off;  // the wipers a course starts with
    KeyBindings keys;

    // The hint "Esc: menu and controls" is shown until the player has opened the menu.
    bool menu_seen = false;

    bool operator==(const Settings&) const = default;
};

// Ranges a value must lie in; outside them the file's value is refused.
inline constexpr float kMinAutoScale = 0.25f;
inline constexpr int kMinWindowSide = 320;
inline constexpr int kMaxWindowSide = 16384;

nlohmann::json settings_to_json(const Settings& settings);

// `json` read into settings: what is missing keeps its default, and what is wrong (a
// value of the wrong type or out of range, an unknown name, keys two actions share)
// falls back to its default with one line in `problems` naming the key.
Settings settings_from_json(const nlohmann::json& json, std::vector<std::string>& problems);

// `stored` with the changes the player made between `before` and `after` (the
// settings this run used, which may differ from the file's by command-line options):
// a change goes to the file, an option given for one run does not.
Settings with_changes(const Settings& stored, const Settings& before, const Settings& after);

const char* camera_setting_name(sim::ViewMode view);
const char* wiper_setting_name(sim::WiperMode mode);

}  // namespace game
