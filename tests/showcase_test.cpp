// Each bundled effect replay has a showcase checkpoint: its scripted camera (the
// replay's camera shots, docs/REPLAYS.md) shows the effect up close. The checkpoint's
// frame is rendered as the replay renders it, once with every pass and once without
// the effect's, and at least 10% of its pixels must change. The same frame seen from
// the camera turned round must change under 1%: the measure sees the effect, not
// noise. Set SPINDRIFT_SHOWCASE_PNG_DIR to write the two frames of each as PNGs.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "effects/scene/WeatherLook.h"
#include "effects/water/WaterPass.h"
#include "effects/water/WaterView.h"
#include "game/capture/ImageFiles.h"
#include "game/replay/CameraTrack.h"
#include "game/replay/ReplayReader.h"
#include "sim/player/CameraRig.h"

namespace {

namespace fs = std::filesystem;

// A pixel has changed when one of its channels moved by more than this (of 255): twice
// the 5/255 a golden comparison forgives as rasteriser noise, so only what the effect
// draws counts, yet a thin veil of dust or a faint film of water does.
constexpr int kChangedChannel = 10;
constexpr double kShowcaseShare = 0.10;  // the bar: the effect fills a tenth of the frame
constexpr double kTurnedAwayShare = 0.01;

fs::path replay_path(const std::string& name) {
    return fs::path(SPINDRIFT_TEST_DATA).parent_path().parent_path() / "replays" / (name + ".replay");
}

double changed_share(const game::ImageRGBA8& a, const game::ImageRGBA8& b) {
    EXPECT_EQ(a.pixels.size(), b.pixels.size());
    size_t changed = 0;
    for (size_t i = 0; i + 3 < a.pixels.size() && i + 3 < b.pixels.size(); i += 4) {
        int most = 0;
        for (size_t c = 0; c < 3; ++c) most = std::max(most, std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])));
        changed += most > kChangedChannel;
    }
    return double(changed) / double(std::max<size_t>(a.pixels.size() / 4, 1));
}

class ShowcaseTest : public HeadlessTest {
protected:
    struct Shares {
        double scripted = 0.0;    // from the checkpoint's scripted camera
        double turned_away = 0.0;  // from the same eye, looking the other way
    };

    // Replays `name` to its checkpoint `tick` and renders that frame at the replay's frame
    // size from the camera its shots give, with every pass and as `without` says.
    // `without` gets the stage, to draw a pass's own view of the sim.
    Shares effect_share(const std::string& name, uint32_t tick,
                        const std::function<StageFrame(RenderStage&)>& without) {
        const game::Replay replay = game::read_replay(replay_path(name));
        const game::ReplayHeader& h = replay.header;
        EXPECT_TRUE(std::find(h.checkpoints.begin(), h.checkpoints.end(), tick) != h.checkpoints.end())
            << name << " has no checkpoint " << tick;
        EXPECT_LE(tick, replay.inputs.size());
        RenderStage stage(game::GameSession::open(h.level_id, 1, h.seed),
                          {.width = int(h.frame_width), .height = int(h.frame_height)});
        for (uint32_t t = 0; t < tick && t < replay.inputs.size(); ++t) stage.world().step(replay.inputs[t]);
        const game::CameraTrack cameras(h.camera_shots, h.tick_rate_hz);
        const sim::CameraView view = cameras.view_at(tick, stage.world().get<sim::CameraRig>().view());
        sim::CameraView away = view;
        away.target = view.eye - (view.target - view.eye);

        const double time_s = double(tick) * sim::kTickSeconds;
        StageFrame off = without(stage);
        off.time_s = time_s;
        Shares s;
        const game::ImageRGBA8 with = stage.render(view, {.time_s = time_s});
        const game::ImageRGBA8 without_effect = stage.render(view, off);
        s.scripted = changed_share(with, without_effect);
        s.turned_away = changed_share(stage.render(away, {.time_s = time_s}), stage.render(away, off));
        if (const char* dir = std::getenv("SPINDRIFT_SHOWCASE_PNG_DIR")) {
            game::write_png(fs::path(dir) / (name + "_" + std::to_string(tick) + ".png"), with);
            game::write_png(fs::path(dir) / (name + "_" + std::to_string(tick) + "_without.png"), without_effect);
        }
        return s;
    }

    static std::function<StageFrame(RenderStage&)> skipping(StagePasses passes) {
        return [passes](RenderStage&) { return StageFrame{.skip = passes}; };
    }

    static void expect_showcase(const Shares& s) {
        std::printf("the effect changes %.1f%% of the frame, %.2f%% turned away\n", 100.0 * s.scripted,
                    100.0 * s.turned_away);
        EXPECT_GE(s.scripted, kShowcaseShare) << "the effect changes " << 100.0 * s.scripted << "% of the frame";
        EXPECT_LT(s.turned_away, kTurnedAwayShare)
            << "turned away from the effect, " << 100.0 * s.turned_away << "% of the frame still changes";
    }
};

// The water without the splashes: the wave grid as it is, no sheets and no spray.
std::function<StageFrame(RenderStage&)> without_splashes() {
    return [](RenderStage& stage) {
        StageFrame f;
        f.replaced = kWaterPass;
        f.replacement = [&stage](const effects::FrameContext& frame) {
            effects::WaterView view;
            effects::gather_water_view(stage.world(), view);
            view.sheets.clear();
            view.spray.clear();
            stage.pass<effects::WaterPass>().draw(frame, view);
        };
        return f;
    };
}

// The first stone's crown close up from the side.
TEST_F(ShowcaseTest, BoatSplashCrownFillsItsCheckpoint) {
    expect_showcase(effect_share("harbour_boat", 682, without_splashes()));
}

// A shot seen side-on: the beam and the light it casts.
TEST_F(ShowcaseTest, EnergyBeamSideOnFillsItsCheckpoint) {
    expect_showcase(effect_share("harbour_energy", 150, skipping(kEnergyPass | kEnergyLightPass)));
}

// The tank close up, its liquid and spray.
TEST_F(ShowcaseTest, TankLiquidFillsItsCheckpoint) {
    expect_showcase(effect_share("harbour_tank", 1035, skipping(kFluidPass)));
}

// A dusty prop close up, with the patch a shot cleared.
TEST_F(ShowcaseTest, DustyShelfFillsItsCheckpoint) {
    expect_showcase(effect_share("harbour_dust", 1010, skipping(kDustPass)));
}

// Rain on the windshield from the driver's seat, parked with the wipers off.
TEST_F(ShowcaseTest, RainOnTheGlassFillsItsCheckpoint) {
    expect_showcase(effect_share("harbour_rain", 1690, skipping(kRainPass)));
}

}  // namespace
