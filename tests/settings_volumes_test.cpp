// The player's volumes (settings.json, the menu's Settings page, the F1 panel) as the
// mixer gets them: the play loop hands it mixer_volumes(settings.volume) at the start
// and after every change.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "AudioAnalysis.h"
#include "AudioReplays.h"
#include "game/audio/SettingsVolumes.h"
#include "game/settings/Settings.h"

namespace {

using namespace audio_test;

TEST(SettingsVolumes, EachBusGetsItsOwnSetting) {
    game::Settings::Volumes set{.master = 0.25f, .engine = 0.0f, .effects = 1.0f, .ambience = 0.5f};
    const audio::Volumes v = game::mixer_volumes(set);
    EXPECT_EQ(v.master, 0.25f);
    EXPECT_EQ(v.engine, 0.0f);
    EXPECT_EQ(v.effects, 1.0f);
    EXPECT_EQ(v.ambience, 0.5f);
}

TEST(SettingsVolumes, TheFilesVolumesReachTheMixer) {
    std::vector<std::string> problems;
    const game::Settings s = game::settings_from_json(
        nlohmann::json{{"volume", {{"master", 0.5}, {"engine", 0.2}, {"effects", 0.9}, {"ambience", 0.1}}}}, problems);
    ASSERT_TRUE(problems.empty());
    game::SessionSound sound;
    sound.mixer().set_volumes(game::mixer_volumes(s.volume));
    EXPECT_EQ(sound.mixer().volumes().master, 0.5f);
    EXPECT_EQ(sound.mixer().volumes().engine, 0.2f);
    EXPECT_EQ(sound.mixer().volumes().effects, 0.9f);
    EXPECT_EQ(sound.mixer().volumes().ambience, 0.1f);
}

TEST(SettingsVolumes, OutOfRangeIsHeldToTheUnit) {
    const audio::Volumes v = game::mixer_volumes({.master = 1.5f, .engine = -0.5f, .effects = 0.3f, .ambience = 2.0f});
    EXPECT_EQ(v.master, 1.0f);
    EXPECT_EQ(v.engine, 0.0f);
    EXPECT_EQ(v.effects, 0.3f);
    EXPECT_EQ(v.ambience, 1.0f);
}

TEST(SettingsVolumes, MasterAtZeroSilencesAPlayingMix) {
    const game::Replay replay = bundled("harbour_drive");
    game::GameSession session = game::GameSession::open(replay.header.level_id, 1, replay.header.seed);
    game::SessionSound sound;
    sound.mixer().set_volumes(game::mixer_volumes(game::Settings{}.volume));
    std::vector<float> block(2 * 512);
    for (size_t i = 0; i < 120; ++i) {
        session.world->step(replay.inputs[i]);
        sound.after_tick(*session.world);
    }
    sound.mixer().render(block.data(), 512);
    EXPECT_GT(power(block, 0, block.size()), 1e-6) << "at the default settings there is sound";
    game::Settings::Volumes off = game::Settings{}.volume;
    off.master = 0.0f;
    sound.mixer().set_volumes(game::mixer_volumes(off));
    for (int i = 0; i < 40; ++i) sound.mixer().render(block.data(), 512);  // the per-block smoothing
    EXPECT_LT(power(block, 0, block.size()), 1e-12) << "master at 0 in the settings: silence";
}

}  // namespace
