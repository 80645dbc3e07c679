// The offline render of the bundled replays, listened to: the same samples every time,
// the sim untouched, every event heard at its tick, loud enough and never clipping.
#include <gtest/gtest.h>

#include <cstring>
#include <map>

#include "AudioAnalysis.h"
#include "AudioReplays.h"
#include "audio/models/NoiseBed.h"
#include "game/replay/ReplayCheck.h"
#include "sim/player/Player.h"

namespace {

using namespace audio_test;

TEST(AudioRender, TwoRendersOfAReplayAreBitIdentical) {
    const Render a = render("harbour_rain", 300);
    const Render b = render("harbour_rain", 300);
    ASSERT_EQ(a.samples.size(), size_t(300 * 2 * kTickFrames));
    ASSERT_EQ(a.samples.size(), b.samples.size());
    EXPECT_EQ(std::memcmp(a.samples.data(), b.samples.data(), a.samples.size() * sizeof(float)), 0);
    EXPECT_GT(power(mono(a.samples), 0, a.samples.size() / 2), 1e-6) << "the render is silent";
}

// The spatialisation is the mixer's: OpenAL, its settings pinned, must play the mix as it is.
TEST(AudioRender, OpenAlsLoopbackPassesTheMixThroughUnchanged) {
    game::OfflineSound pin(game::CameraTrack{});  // pins OpenAL's settings before it starts, like a render
    audio::Mixer through, direct;
    audio::NoiseBed a(audio::Bus::Effects, audio::NoiseBand{}), b(audio::Bus::Effects, audio::NoiseBand{});
    a.set(1.0f);
    b.set(1.0f);
    through.add(a);
    direct.add(b);
    through.update_placement({}, 1.0f / 60.0f);
    direct.update_placement({}, 1.0f / 60.0f);
    std::string why;
    auto loopback = audio::LoopbackRender::open(through, why);
    ASSERT_TRUE(loopback) << why;
    std::vector<float> x(2 * kTickFrames), y(2 * kTickFrames);
    for (int t = 0; t < 60; ++t) {
        loopback->render(x.data(), kTickFrames);
        direct.render(y.data(), kTickFrames);
        ASSERT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(float)), 0) << "tick " << t;
    }
    EXPECT_GT(power(x, 0, x.size()), 1e-6);
}

TEST(AudioRender, TheSimHashesTheSameWithSoundAsRecorded) {
    const game::Replay replay = bundled("harbour_energy");
    game::GameSession session = game::GameSession::open(replay.header.level_id, 1, replay.header.seed);
    game::OfflineSound offline(game::CameraTrack(replay.header.camera_shots, replay.header.tick_rate_hz));
    game::ReplayChecker checker(replay);
    std::optional<game::Divergence> divergence;
    game::TickDriver driver(*session.world);
    driver.listen([&](const sim::World& w, sim::TickInput) { offline.after_tick(w); });
    driver.listen([&](const sim::World& w, sim::TickInput) {
        if (!divergence) divergence = checker.after_step(w);
    });
    for (const sim::TickInput& input : replay.inputs) driver.step(input);
    EXPECT_FALSE(divergence) << divergence->message;
    EXPECT_EQ(checker.hashes_checked(), replay.inputs.size());
}

TEST(AudioRender, PausedIsSilentAndResumes) {
    const game::Replay replay = bundled("harbour_drive");
    game::GameSession session = game::GameSession::open(replay.header.level_id, 1, replay.header.seed);
    game::SessionSound sound;
    std::vector<float> block(2 * 512);
    for (size_t i = 0; i < 120; ++i) {
        session.world->step(replay.inputs[i]);
        sound.after_tick(*session.world);
    }
    sound.mixer().render(block.data(), 512);
    EXPECT_GT(power(block, 0, block.size()), 1e-6) << "playing, there is sound";
    sound.mixer().set_paused(true);
    for (int i = 0; i < 40; ++i) sound.mixer().render(block.data(), 512);  // the fade: under half a second
    for (int i = 0; i < 20; ++i) {
        sound.mixer().render(block.data(), 512);
        for (float x : block) ASSERT_EQ(x, 0.0f) << "paused, every sample is zero";
    }
    sound.mixer().set_paused(false);
    for (int i = 0; i < 10; ++i) sound.mixer().render(block.data(), 512);
    EXPECT_GT(power(block, 0, block.size()), 1e-6) << "resumed, the sound comes back";
}

class BundledReplaySound : public ::testing::TestWithParam<const char*> {};

TEST_P(BundledReplaySound, IsLoudEnoughNeverClipsAndHearsEveryEvent) {
    const Render r = render(GetParam(), 0);
    ASSERT_FALSE(r.samples.empty());
    if (auto bad = bad_sample(r.samples)) FAIL() << "sample " << *bad << " is " << r.samples[*bad];
    const Loudness l = loudness(r.samples);
    EXPECT_GE(l.integrated_lufs, -26.0);
    EXPECT_LE(l.integrated_lufs, -20.0);
    EXPECT_LE(l.true_peak_dbtp, -1.0);
    // Onsets on the effects alone: the engine and the beds are the background they rise from.
    const Render fx = render(GetParam(), 0, audio::Volumes{1.0f, 0.0f, 1.0f, 0.0f});
    const std::vector<float> m = mono(fx.samples);
    int events = 0, heard = 0;
    std::map<std::string, int> kinds;
    std::string missed;
    for (size_t i = 0; i < fx.ticks.size(); ++i) {
        if (!fx.ticks[i].event) continue;
        ++events;
        for (unsigned bit = 1; bit <= kCue; bit <<= 1)
            if (fx.ticks[i].events & bit) ++kinds[event_names(bit)];
        // Events one tick apart share an onset.
        const bool near = onset_near(m, fx.ticks[i].tick) || (i > 0 && fx.ticks[i - 1].event && onset_near(m, fx.ticks[i - 1].tick));
        if (near) ++heard;
        else missed += " " + std::to_string(fx.ticks[i].tick) + " (" + event_names(fx.ticks[i].events) + ")";
    }
    EXPECT_EQ(heard, events) << "events with no onset within a tick, at ticks" << missed;
    // Each kind of event is in some bundled replay, so none is checked vacuously.
    const std::map<std::string, unsigned> expected{
        {"harbour_boat", kSplash | kCue},       {"harbour_drive", kCue},
        {"harbour_dust", kKnock | kShotFired | kShotImpact},
        {"harbour_energy", kShotFired | kShotImpact | kSplash},
        {"harbour_goals", kCue | kSplash},      {"harbour_rain", kWiperReversal}, {"harbour_tank", 0u}};
    unsigned seen = 0;
    for (const TickLog& t : fx.ticks) seen |= t.events;
    EXPECT_EQ(seen & expected.at(GetParam()), expected.at(GetParam())) << "missing: " << event_names(expected.at(GetParam()) & ~seen);
    std::cout << GetParam() << ": " << l.integrated_lufs << " LUFS, true peak " << l.true_peak_dbtp << " dBTP, "
              << events << " events, " << heard << " heard:";
    for (const auto& [kind, n] : kinds) std::cout << " " << n << " " << kind;
    std::cout << "\n";
}

INSTANTIATE_TEST_SUITE_P(Replays, BundledReplaySound,
                         ::testing::Values("harbour_boat", "harbour_drive", "harbour_dust", "harbour_energy",
                                           "harbour_goals", "harbour_rain", "harbour_tank"));

}  // namespace
