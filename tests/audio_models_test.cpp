// The sound models against the state that drives them, measured on offline renders of
// the bundled replays: the rain's bed follows the rain rate, the engine's pitch follows
// its rpm, and the cabin keeps the outside rain's highs out.
#include <gtest/gtest.h>

#include "AudioAnalysis.h"
#include "AudioReplays.h"
#include "sim/vehicle/Boat.h"
#include "sim/water/WaterSim.h"

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

namespace {

using namespace audio_test;

constexpr audio::Volumes kEffectsOnly{1.0f, 0.0f, 1.0f, 0.0f};

sim::TickInput tap(sim::Control c) {
    sim::TickInput in;
    in.set(c, true);
    return in;
}

// The harbour's rain replay's level and seed, with inputs of our own.
game::Replay scripted(std::vector<sim::TickInput> inputs) {
    game::Replay r = bundled("harbour_rain");
    r.header.camera_shots.clear();
    r.inputs = std::move(inputs);
    return r;
}

// The squeak's band against the swish's, dB: the squeak is a tone at 1150-1370 Hz, the
// swish a broad band around 2.4 kHz.
double squeak_over_swish(const std::vector<float>& m, size_t from_tick, size_t to_tick) {
    const size_t a = from_tick * kTickFrames, b = to_tick * kTickFrames;
    const std::vector<float> squeak = bandpass(m, 1080.0, 1450.0), swish = bandpass(m, 2000.0, 3500.0);
    return db(power(squeak, a, b)) - db(power(swish, a, b));
}

TEST(WiperSound, TheBladesSqueakAsTheGlassDriesAndNotWhileItIsWet) {
    // In the driver's seat: the rain set in, the wipers on high, then the rain stopped
    // with the wipers left running until the glass they sweep is dry.
    std::vector<sim::TickInput> in(2400);
    in[0] = tap(sim::Control::Camera);
    for (size_t t : {2, 4, 6}) in[t] = tap(sim::Control::RainUp);
    for (size_t t : {300, 302, 304}) in[t] = tap(sim::Control::Wipers);
    for (size_t t : {900, 902, 904}) in[t] = tap(sim::Control::RainDown);
    const Render r = render(scripted(in), 0, kEffectsOnly);
    ASSERT_EQ(r.ticks.size(), in.size());
    const std::vector<float> m = mono(r.samples);
    const size_t wet_from = 420, wet_to = 900, dry_from = 1700, dry_to = 2400;

    // What the wipers were told: no squeak while the rain keeps the sweep wet, a
    // squeak on most ticks once the glass they sweep is dry.
    int dry_squeaks = 0;
    for (size_t t = wet_from; t < wet_to; ++t) {
        ASSERT_GT(r.ticks[t].rain_rate, 0.5f);
        ASSERT_EQ(r.ticks[t].sound.squeak, 0.0f) << "tick " << t << ", wetness " << r.ticks[t].sound.glass_wetness;
    }
    for (size_t t = dry_from; t < dry_to; ++t) dry_squeaks += r.ticks[t].sound.squeak > 0.0f;
    EXPECT_GT(dry_squeaks, int(dry_to - dry_from) / 2) << "ticks with a squeak on the dry glass";

    // Heard: in the squeak's band (1080-1450 Hz) a tone, in most 20 ms windows of the
    // dry sweep and far fewer of the wet one (where the swish's noise fills the band),
    // and the band rises over the swish's.
    const std::vector<float> band = bandpass(m, 1080.0, 1450.0);
    const auto tonal = [&](size_t from_tick, size_t to_tick) {
        int tone = 0, windows = 0;
        for (size_t w = from_tick * kTickFrames; w + 1100 < to_tick * kTickFrames; w += 960, ++windows) {
            const double f = pitch_hz(band, kRate, w, 960, 1000.0, 1500.0);
            tone += f > 1100.0 && f < 1420.0;
        }
        return double(tone) / double(windows);
    };
    const double tonal_wet = tonal(wet_from, wet_to), tonal_dry = tonal(dry_from, dry_to);
    EXPECT_GT(tonal_dry, 0.6);
    EXPECT_GT(tonal_dry, tonal_wet + 0.3) << "wet " << tonal_wet;
    const double wet_db = squeak_over_swish(m, wet_from, wet_to), dry_db = squeak_over_swish(m, dry_from, dry_to);
    EXPECT_GT(dry_db, wet_db + 8.0) << "the squeak's band over the swish's, wet " << wet_db << " dB, dry " << dry_db << " dB";
    std::cout << "squeak: tonal windows wet " << tonal_wet << ", dry " << tonal_dry << "; band over swish wet " << wet_db
              << " dB, dry " << dry_db << " dB\n";
}

}  // namespace

namespace {

using namespace audio_test;

struct HullHeard {
    int slaps = 0;
    double energy = 0.0;  // the slaps' summed strength squared, as the soundscape started them
    double band_db = 0.0; // the effects bus at the boat, 60-1000 Hz
};

// The boat moored, nobody at the helm, heard from beside it for ten seconds while a
// wave of `depth_m` is pushed into the sea 5 m off its bow every two seconds.
HullHeard hull_in_waves(float depth_m) {
    const game::Replay replay = bundled("harbour_boat");
    game::GameSession session = game::GameSession::open(replay.header.level_id, 1, replay.header.seed);
    sim::World& world = *session.world;
    const auto beside_the_boat = [](const sim::World& w, const sim::CameraView&) {
        const sim::Boat& boat = w.get<sim::Boat>();
        audio::Listener l;
        l.position = boat.position() + boat.pose().right_flat() * 4.0f + glm::vec3(0.0f, 1.5f, 0.0f);
        l.forward = -boat.pose().right_flat();
        return l;
    };
    game::OfflineSound offline(game::CameraTrack{}, beside_the_boat);
    offline.sound().mixer().set_volumes(kEffectsOnly);
    HullHeard h;
    std::vector<float> samples;
    for (int t = 0; t < 600; ++t) {
        if (depth_m > 0.0f && t % 120 == 60) {
            const sim::Boat& boat = world.get<sim::Boat>();
            const glm::vec3 off_bow = boat.position() + boat.pose().forward_flat() * 5.0f;
            world.get<sim::WaterSim>().disturb({off_bow.x, off_bow.z}, 3.0f, depth_m);
        }
        world.step(sim::TickInput{});
        const std::vector<float>& tick = offline.after_tick(world);
        samples.insert(samples.end(), tick.begin(), tick.end());
        h.slaps += offline.sound().soundscape().state().hull_slaps;
        h.energy += offline.sound().soundscape().state().slap_energy;
    }
    h.band_db = db(power(bandpass(mono(samples), 60.0, 1000.0), 0, samples.size() / 2));
    return h;
}

TEST(HullSound, TheWaterSlapsTheHullInWavesAndNotOnACalmSea) {
    const HullHeard calm = hull_in_waves(0.0f), waves = hull_in_waves(0.6f);
    std::cout << "hull: calm " << calm.slaps << " slaps, " << calm.band_db << " dB; waves " << waves.slaps
              << " slaps, energy " << waves.energy << ", " << waves.band_db << " dB\n";
    EXPECT_EQ(calm.slaps, 0) << "a calm sea does not slap a moored boat";
    EXPECT_GE(waves.slaps, 5) << "five waves pass under the hull";
    EXPECT_GT(waves.band_db, calm.band_db + 10.0) << "the slaps are heard";
}

}  // namespace
