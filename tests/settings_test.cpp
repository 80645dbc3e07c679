// The player's settings: settings.json read and written (atomically, only on a change),
// what a bad file falls back to, the command line's changes kept out of the file, and
// key bindings that never give one key two actions.
#include "game/play/PauseMenu.h"
#include "game/play/ResolutionController.h"
#include "game/settings/KeyBindings.h"
#include "game/settings/KeyNames.h"
#include "game/settings/Settings.h"
#include "game/settings/SettingsFile.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace fs = std::filesystem;
using game::Action;
using game::KeyBindings;
using game::Settings;
using nlohmann::json;

namespace {

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() / ("spindrift_settings_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

std::string read(const fs::path& p) {
    std::stringstream s;
    s << std::ifstream(p, std::ios::binary).rdbuf();
    return s.str();
}

Settings from(const json& j, std::vector<std::string>& problems) { return game::settings_from_json(j, problems); }

// Every field away from its default.
Settings changed() {
    Settings s;
    s.quality = game::QualityChoice::High;
    s.auto_min_scale = 0.5f;
    s.auto_max_scale = 0.9f;
    s.window = {.width = 1600, .height = 900, .x = 40, .y = -20, .fullscreen = true};
    s.vsync = false;
    s.fxaa = true;
    s.volume = {.master = 0.25f, .engine = 0.0f, .effects = 1.0f, .ambience = 0.5f};
    s.camera = sim::ViewMode::Driver;
    s.wipers = sim::WiperMode::Low;
    EXPECT_TRUE(s.keys.bind(Action::Fire, 0, GLFW_KEY_J).bound);
    s.menu_seen = true;
    return s;
}

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
    for (const std::string& p : problems)
        if (p.find(text) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST(Settings, DefaultsAndChangesSurviveTheirJson) {
    for (const Settings& s : {Settings{}, changed()}) {
        std::vector<std::string> problems;
        // Through the text too, as the file holds it.
        EXPECT_EQ(from(json::parse(game::settings_to_json(s).dump(2)), problems), s);
        EXPECT_TRUE(problems.empty()) << problems.front();
    }
    EXPECT_FALSE(changed() == Settings{});
}

TEST(Settings, AutosDefaultRangeIsTheResolutionControllers) {
    const game::ResolutionController::Options controller;
    EXPECT_EQ(Settings{}.auto_min_scale, controller.min_scale);
    EXPECT_EQ(Settings{}.auto_max_scale, controller.max_scale);
}

TEST(Settings, AMissingSettingKeepsItsDefault) {
    std::vector<std::string> problems;
    const Settings s = from(json{{"version", 1}, {"quality", "low"}}, problems);
    EXPECT_TRUE(problems.empty());
    EXPECT_EQ(s.quality, game::QualityChoice::Low);
    Settings expected;
    expected.quality = game::QualityChoice::Low;
    EXPECT_EQ(s, expected);
}

TEST(Settings, AWrongValueFallsBackAloneWithALineNamingItsKey) {
    json j = game::settings_to_json(changed());
    j["volume"]["master"] = 1.5;
    j["window"]["width"] = 10;
    j["quality"] = "ultra";
    j["vsync"] = "yes";
    j["auto_render_scale"] = {{"min", 0.9}, {"max", 0.4}};
    std::vector<std::string> problems;
    const Settings s = from(j, problems);
    ASSERT_EQ(problems.size(), 5u);
    EXPECT_TRUE(mentions(problems, "volume.master: 1.5 is outside 0..1"));
    EXPECT_TRUE(mentions(problems, "window.width"));
    EXPECT_TRUE(mentions(problems, "quality: \"ultra\" is not one of low, medium, high, auto"));
    EXPECT_TRUE(mentions(problems, "vsync"));
    EXPECT_TRUE(mentions(problems, "auto_render_scale: min is above max"));
    const Settings defaults;
    EXPECT_EQ(s.volume.master, defaults.volume.master);
    EXPECT_EQ(s.window.width, defaults.window.width);
    EXPECT_EQ(s.quality, defaults.quality);
    EXPECT_EQ(s.vsync, defaults.vsync);
    EXPECT_EQ(s.auto_min_scale, defaults.auto_min_scale);
    // What was right is kept.
    EXPECT_EQ(s.volume.ambience, 0.5f);
    EXPECT_EQ(s.window.height, 900);
    EXPECT_EQ(s.camera, sim::ViewMode::Driver);
    EXPECT_EQ(s.keys, changed().keys);
}

TEST(Settings, ANewerVersionGivesTheDefaults) {
    json j = game::settings_to_json(changed());
    j["version"] = Settings::kVersion + 1;
    std::vector<std::string> problems;
    EXPECT_EQ(from(j, problems), Settings{});
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_TRUE(mentions(problems, "version: 2 is from a newer Spindrift"));
}

TEST(Settings, UnknownSettingsAndNonObjectsAreNamed) {
    std::vector<std::string> problems;
    from(json{{"colour", "red"}, {"window", 3}}, problems);
    EXPECT_EQ(problems.size(), 2u);
    EXPECT_TRUE(mentions(problems, "colour: not a setting"));
    EXPECT_TRUE(mentions(problems, "window: expected an object"));
    problems.clear();
    EXPECT_EQ(from(json::array({1, 2}), problems), Settings{});
    EXPECT_EQ(problems.size(), 1u);
}

TEST(Settings, ABadKeyFallsBackForItsActionOnly) {
    json j = game::settings_to_json(changed());
    j["keys"]["camera"] = {"NoSuchKey"};
    j["keys"]["wipers"] = {"Esc"};
    j["keys"]["dance"] = {"K"};
    std::vector<std::string> problems;
    const Settings s = from(j, problems);
    EXPECT_EQ(problems.size(), 3u);
    EXPECT_TRUE(mentions(problems, "keys.camera"));
    EXPECT_TRUE(mentions(problems, "keys.wipers"));
    EXPECT_TRUE(mentions(problems, "keys.dance: no such action"));
    EXPECT_EQ(s.keys.keys(Action::Camera), KeyBindings().keys(Action::Camera));
    EXPECT_EQ(s.keys.keys(Action::Fire)[0], GLFW_KEY_J);  // the others are kept
}

TEST(Settings, KeysTwoActionsShareAreRefused) {
    json j = game::settings_to_json(Settings{});
    j["keys"]["fire"] = {"W"};
    std::vector<std::string> problems;
    const Settings s = from(j, problems);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_TRUE(mentions(problems, "keys.fire: shares a key with keys.throttle"));
    EXPECT_EQ(s.keys, KeyBindings());
}

TEST(Settings, AChangeGoesToTheFileAndARunsOptionDoesNot) {
    Settings stored;
    stored.quality = game::QualityChoice::High;
    Settings before = stored;
    before.quality = game::QualityChoice::Low;  // --quality low for this run
    before.window.fullscreen = true;            // --fullscreen
    Settings after = before;
    after.fxaa = true;
    after.volume.engine = 0.3f;
    const Settings kept = game::with_changes(stored, before, after);
    EXPECT_EQ(kept.quality, game::QualityChoice::High);
    EXPECT_FALSE(kept.window.fullscreen);
    EXPECT_TRUE(kept.fxaa);
    EXPECT_EQ(kept.volume.engine, 0.3f);
    // Changing the overridden setting itself keeps the player's new choice.
    after.quality = game::QualityChoice::Medium;
    EXPECT_EQ(game::with_changes(stored, before, after).quality, game::QualityChoice::Medium);
}

TEST(SettingsFile, NoFileGivesTheDefaultsAndWritesNothing) {
    TempDir dir;
    const fs::path path = dir.path / "spindrift" / "settings.json";
    game::SettingsFile file(path);
    EXPECT_EQ(file.settings(), Settings{});
    EXPECT_TRUE(file.problems().empty());
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path.parent_path()));
}

TEST(SettingsFile, SavedAtomicallyAndReadBack) {
    TempDir dir;
    const fs::path path = dir.path / "spindrift" / "settings.json";
    {
        game::SettingsFile file(path);
        std::string error;
        ASSERT_TRUE(file.save(changed(), error)) << error;
    }
    EXPECT_TRUE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path.string() + ".tmp"));
    const json on_disk = json::parse(read(path));
    EXPECT_EQ(on_disk["version"], Settings::kVersion);
    EXPECT_EQ(on_disk["keys"]["fire"], json::array({"J"}));
    EXPECT_EQ(on_disk["volume"]["master"], 0.25);
    game::SettingsFile again(path);
    EXPECT_TRUE(again.problems().empty());
    EXPECT_EQ(again.settings(), changed());
}

TEST(SettingsFile, ACorruptFileIsNamedAndLeftAloneUntilAChange) {
    TempDir dir;
    const fs::path path = dir.path / "settings.json";
    const std::string corrupt = "{\"quality\": \"low\",\n  \"vsync\": tru";
    write(path, corrupt);
    game::SettingsFile file(path);
    ASSERT_EQ(file.problems().size(), 1u);
    EXPECT_TRUE(mentions(file.problems(), "is not valid JSON (parse error at line 2"));
    EXPECT_EQ(file.settings(), Settings{});
    std::string error;
    // Nothing changed: the file stays as the player left it.
    EXPECT_TRUE(file.save(file.settings(), error));
    EXPECT_EQ(read(path), corrupt);
    // A change replaces it with a whole, valid file.
    Settings s = file.settings();
    s.vsync = false;
    ASSERT_TRUE(file.save(s, error)) << error;
    EXPECT_EQ(game::SettingsFile(path).settings(), s);
}

TEST(SettingsFile, AFailedWriteSaysWhyAndKeepsTheOldFile) {
    TempDir dir;
    write(dir.path / "not_a_dir", "x");
    game::SettingsFile file(dir.path / "not_a_dir" / "settings.json");
    std::string error;
    EXPECT_FALSE(file.save(changed(), error));
    EXPECT_NE(error.find("cannot write"), std::string::npos) << error;
    EXPECT_EQ(file.settings(), changed());  // still this run's
    EXPECT_EQ(read(dir.path / "not_a_dir"), "x");
}

TEST(SettingsFile, FoundUnderXdgConfigHomeOrHome) {
    const std::string old_xdg = std::getenv("XDG_CONFIG_HOME") ? std::getenv("XDG_CONFIG_HOME") : "";
    const std::string old_home = std::getenv("HOME") ? std::getenv("HOME") : "";
    setenv("HOME", "/home/player", 1);
    setenv("XDG_CONFIG_HOME", "/tmp/cfg", 1);
    EXPECT_EQ(game::default_settings_path(), fs::path("/tmp/cfg/spindrift/settings.json"));
    setenv("XDG_CONFIG_HOME", "relative", 1);  // not absolute: ignored, as the XDG rule says
    EXPECT_EQ(game::default_settings_path(), fs::path("/home/player/.config/spindrift/settings.json"));
    unsetenv("XDG_CONFIG_HOME");
    EXPECT_EQ(game::default_settings_path(), fs::path("/home/player/.config/spindrift/settings.json"));
    old_xdg.empty() ? unsetenv("XDG_CONFIG_HOME") : setenv("XDG_CONFIG_HOME", old_xdg.c_str(), 1);
    old_home.empty() ? unsetenv("HOME") : setenv("HOME", old_home.c_str(), 1);
}

TEST(KeyBindings, ATakenKeySwapsAndSaysSo) {
    KeyBindings k;
    const KeyBindings::Outcome o = k.bind(Action::Fire, 0, GLFW_KEY_E);  // E switches vehicle
    EXPECT_TRUE(o.bound);
    EXPECT_EQ(o.message, "Fire: E (swapped: Switch car / boat now has Space)");
    EXPECT_EQ(k.keys(Action::Fire)[0], GLFW_KEY_E);
    EXPECT_EQ(k.keys(Action::SwitchVehicle)[0], GLFW_KEY_SPACE);
    // Into an empty slot: taken from the other action, which is told.
    const KeyBindings::Outcome taken = k.bind(Action::Fire, 1, GLFW_KEY_W);
    EXPECT_EQ(taken.message, "Fire: W (taken from Throttle)");
    EXPECT_EQ(k.keys(Action::Throttle), (KeyBindings::Keys{0, GLFW_KEY_UP}));
    EXPECT_FALSE(k.first_shared_key());
}

TEST(KeyBindings, EscAndUnnamedKeysAreRefused) {
    KeyBindings k;
    EXPECT_FALSE(k.bind(Action::Fire, 0, GLFW_KEY_ESCAPE).bound);
    EXPECT_FALSE(k.bind(Action::Fire, 0, GLFW_KEY_UNKNOWN).bound);
    EXPECT_FALSE(k.bind(Action::Fire, 2, GLFW_KEY_J).bound);
    EXPECT_EQ(k, KeyBindings());
}

TEST(KeyBindings, NoSequenceOfBindsLeavesAKeyWithTwoActions) {
    KeyBindings k;
    const int keys[] = {GLFW_KEY_W, GLFW_KEY_SPACE, GLFW_KEY_UP, GLFW_KEY_J, GLFW_KEY_F11, GLFW_KEY_E, GLFW_KEY_P};
    unsigned state = 12345;
    for (int i = 0; i < 2000; ++i) {
        state = state * 1103515245u + 12345u;
        const Action a = Action((state >> 8) % game::kActionCount);
        const int slot = int((state >> 4) & 1);
        k.bind(a, slot, keys[(state >> 16) % std::size(keys)]);
        ASSERT_FALSE(k.first_shared_key()) << "after bind " << i;
    }
}

TEST(KeyNames, EveryNamedKeyReadsBack) {
    std::set<std::string> names;
    for (int key = GLFW_KEY_SPACE; key <= game::kKeyAltEnter; ++key) {
        const std::string name = game::key_name(key);
        if (name.empty()) continue;
        EXPECT_TRUE(names.insert(name).second) << name << " names two keys";
        EXPECT_EQ(game::key_from_name(name), key) << name;
    }
    EXPECT_EQ(game::key_name(GLFW_KEY_W), "W");
    EXPECT_EQ(game::key_name(GLFW_KEY_F12), "F12");
    EXPECT_EQ(game::key_name(game::kKeyAltEnter), "Alt+Enter");
    EXPECT_FALSE(game::key_from_name("w"));
    EXPECT_FALSE(game::key_from_name(""));
    // Every default key has a name (the file can hold it).
    for (const game::ActionInfo& a : game::actions())
        for (int key : a.default_keys)
            if (key) {
                EXPECT_FALSE(game::key_name(key).empty()) << a.id;
            }
}

TEST(PauseMenu, TheControlsPageNamesTheGamepadsButtons) {
    EXPECT_EQ(game::gamepad_name(Action::Throttle), "right trigger");
    EXPECT_EQ(game::gamepad_name(Action::Fire), "B");
    EXPECT_EQ(game::gamepad_name(Action::Camera), "RB");
    EXPECT_EQ(game::gamepad_name(Action::Reset), "Back");
    EXPECT_EQ(game::gamepad_name(Action::Screenshot), "");
}
