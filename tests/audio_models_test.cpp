// The sound models against the state that drives them, measured on offline renders of
// the bundled replays: the rain's bed follows the rain rate, the engine's pitch follows
// its rpm, and the cabin keeps the outside rain's highs out.
#include <gtest/gtest.h>

#include "AudioAnalysis.h"
#include "AudioReplays.h"

namespace {

using namespace audio_test;

audio::Listener outside(const sim::World& world, const sim::CameraView& view) {
    audio::Listener l = audio::listener_for(world, view);
    l.in_cabin = false;
    return l;
}

audio::Listener in_cabin(const sim::World& world, const sim::CameraView& view) {
    audio::Listener l = audio::listener_for(world, view);
    l.in_cabin = true;
    return l;
}

constexpr audio::Volumes kAmbienceOnly{1.0f, 0.0f, 0.0f, 1.0f};
constexpr audio::Volumes kEngineOnly{1.0f, 1.0f, 0.0f, 0.0f};

TEST(RainSound, TheBedRisesWithTheRainRate) {
    // harbour_rain turns the rain up at its start; the weather follows with a lag.
    const Render r = render("harbour_rain", 600, kAmbienceOnly, outside);
    const std::vector<float> high = highpass(mono(r.samples), 2000.0);
    std::vector<double> rate, level;
    for (size_t t = 0; t + 15 <= r.ticks.size(); t += 15) {
        rate.push_back(r.ticks[t + 7].rain_rate);
        level.push_back(db(power(high, t * kTickFrames, (t + 15) * kTickFrames)));
    }
    ASSERT_GT(rate.back(), rate.front() + 0.3) << "the replay's rain does not rise";
    EXPECT_GT(rank_correlation(rate, level), 0.9);
    EXPECT_GT(level.back() - level.front(), 12.0) << "the bed at full rain against no rain, dB";
}

TEST(RainSound, TheDriversViewHearsTheOutsideRainAtLeast6dBQuieterAbove2kHz) {
    const Render chase = render("harbour_rain", 500, kAmbienceOnly, outside);
    const Render cabin = render("harbour_rain", 500, kAmbienceOnly, in_cabin);
    const size_t from = 300 * kTickFrames, to = 500 * kTickFrames;  // in full rain
    const double chase_db = db(power(highpass(mono(chase.samples), 2000.0), from, to));
    const double cabin_db = db(power(highpass(mono(cabin.samples), 2000.0), from, to));
    EXPECT_LE(cabin_db, chase_db - 6.0) << "chase " << chase_db << " dB, cabin " << cabin_db << " dB";
}

TEST(EngineSound, ItsFundamentalFollowsTheRpm) {
    const Render r = render("harbour_drive", 900, kEngineOnly);
    constexpr size_t kFactor = 8;
    const int rate = kRate / int(kFactor);
    const std::vector<float> low = decimate(mono(r.samples), kFactor);
    std::vector<double> expected, heard;
    int close = 0, windows = 0;
    for (size_t t = 30; t + 12 < r.ticks.size(); t += 12) {
        // A four-cylinder four-stroke fires twice a revolution.
        const double firing = r.ticks[t].engine_rpm / 30.0;
        const double f = pitch_hz(low, rate, (t * kTickFrames) / kFactor, 600, 20.0, 260.0);
        ++windows;
        if (f <= 0.0) continue;
        expected.push_back(firing);
        heard.push_back(f);
        if (std::fabs(f / firing - 1.0) < 0.08) ++close;
    }
    ASSERT_GT(heard.size(), size_t(windows * 3 / 4)) << "no pitch in most windows";
    EXPECT_GT(close, int(heard.size() * 8 / 10)) << close << " of " << heard.size() << " within 8% of rpm / 30";
    EXPECT_GT(rank_correlation(expected, heard), 0.9);
    // And it does rise: the drive reaches well over twice the idle rpm.
    EXPECT_GT(*std::max_element(heard.begin(), heard.end()), 2.0 * *std::min_element(heard.begin(), heard.end()));
}

TEST(EngineSound, TheGearboxShiftsUpAndDown) {
    const Render r = render("harbour_drive", 900, kEngineOnly);
    int ups = 0, downs = 0;
    for (size_t i = 1; i < r.ticks.size(); ++i) {
        ups += r.ticks[i].gear > r.ticks[i - 1].gear;
        downs += r.ticks[i].gear < r.ticks[i - 1].gear;
    }
    EXPECT_GE(ups, 2);
    EXPECT_GE(downs, 1);
}

}  // namespace
