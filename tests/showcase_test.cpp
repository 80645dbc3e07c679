// Each bundled effect replay has a showcase checkpoint: its scripted camera (the
// replay's camera shots, docs/REPLAYS.md) shows the effect up close. The checkpoint's
// frame is rendered as the replay renders it, once with every pass and once without
// the effect's, and at least 10% of its pixels must change. The same frame seen from
// the camera turned round must change under 1%: the measure sees the effect, not
// noise. Set SPINDRIFT_SHOWCASE_PNG_DIR to write the two frames of each as PNGs.
// The dust's showcase also shows the patch the car's shot blew off a crate: there the
// frame barely changes without the dust pass, and around it a lot (the PNG directory
// gets its frame with the patch marked red and the dust around it blue).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "effects/scene/WeatherLook.h"
#include "effects/water/WaterPass.h"
#include "effects/water/WaterView.h"
#include "game/capture/ImageFiles.h"
#include "game/replay/CameraTrack.h"
#include "game/replay/ReplayReader.h"
#include "sim/dust/DustField.h"
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

// The most any colour channel of pixel i moved between two frames, of 255.
int pixel_change(const game::ImageRGBA8& a, const game::ImageRGBA8& b, size_t i) {
    int most = 0;
    for (size_t c = 0; c < 3; ++c) most = std::max(most, std::abs(int(a.pixels[i * 4 + c]) - int(b.pixels[i * 4 + c])));
    return most;
}

double changed_share(const game::ImageRGBA8& a, const game::ImageRGBA8& b) {
    EXPECT_EQ(a.pixels.size(), b.pixels.size());
    const size_t pixels = std::min(a.pixels.size(), b.pixels.size()) / 4;
    size_t changed = 0;
    for (size_t i = 0; i < pixels; ++i) changed += pixel_change(a, b, i) > kChangedChannel;
    return double(changed) / double(std::max<size_t>(a.pixels.size() / 4, 1));
}

void maybe_write(const game::ImageRGBA8& image, const std::string& name) {
    if (const char* dir = std::getenv("SPINDRIFT_SHOWCASE_PNG_DIR")) game::write_png(fs::path(dir) / (name + ".png"), image);
}

class ShowcaseTest : public HeadlessTest {
protected:
    struct Shares {
        double scripted = 0.0;    // from the checkpoint's scripted camera
        double turned_away = 0.0;  // from the same eye, looking the other way
    };

    // A replay's world at one of its checkpoints, on a stage at the replay's frame size,
    // seen as the replay renders that frame.
    struct Checkpoint {
        std::unique_ptr<RenderStage> stage;
        sim::CameraView view;  // from the camera the replay's shots give at the tick
        double time_s = 0.0;
        std::vector<float> dust_at_start;  // the dust amounts before the first tick
    };

    static Checkpoint replay_to(const std::string& name, uint32_t tick) {
        const game::Replay replay = game::read_replay(replay_path(name));
        const game::ReplayHeader& h = replay.header;
        EXPECT_TRUE(std::find(h.checkpoints.begin(), h.checkpoints.end(), tick) != h.checkpoints.end())
            << name << " has no checkpoint " << tick;
        EXPECT_LE(tick, replay.inputs.size());
        Checkpoint c;
        c.stage = std::make_unique<RenderStage>(game::GameSession::open(h.level_id, 1, h.seed),
                                                StageOptions{.width = int(h.frame_width), .height = int(h.frame_height)});
        sim::World& world = c.stage->world();
        const std::span<const float> dust = world.get<sim::DustField>().amounts();
        c.dust_at_start.assign(dust.begin(), dust.end());
        for (uint32_t t = 0; t < tick && t < replay.inputs.size(); ++t) world.step(replay.inputs[t]);
        const game::CameraTrack cameras(h.camera_shots, h.tick_rate_hz);
        c.view = cameras.view_at(tick, world.get<sim::CameraRig>().view());
        c.time_s = double(tick) * sim::kTickSeconds;
        return c;
    }

    // Replays `name` to its checkpoint `tick` and renders that frame with every pass and
    // as `without` says. `without` gets the stage, to draw a pass's own view of the sim.
    Shares effect_share(const std::string& name, uint32_t tick,
                        const std::function<StageFrame(RenderStage&)>& without) {
        Checkpoint c = replay_to(name, tick);
        RenderStage& stage = *c.stage;
        sim::CameraView away = c.view;
        away.target = c.view.eye - (c.view.target - c.view.eye);

        StageFrame off = without(stage);
        off.time_s = c.time_s;
        Shares s;
        const game::ImageRGBA8 with = stage.render(c.view, {.time_s = c.time_s});
        const game::ImageRGBA8 without_effect = stage.render(c.view, off);
        s.scripted = changed_share(with, without_effect);
        s.turned_away = changed_share(stage.render(away, {.time_s = c.time_s}), stage.render(away, off));
        maybe_write(with, name + "_" + std::to_string(tick));
        maybe_write(without_effect, name + "_" + std::to_string(tick) + "_without");
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
    expect_showcase(effect_share("harbour_energy", 150, [](RenderStage&) {
        return StageFrame{.skip = kEnergyPass, .energy = effects::EnergyView{}};  // no glow, no line lights
    }));
}

// The tank close up, its liquid and spray.
TEST_F(ShowcaseTest, TankLiquidFillsItsCheckpoint) {
    expect_showcase(effect_share("harbour_tank", 1035, skipping(kFluidPass)));
}

// The dusty crates close up, with the patch the car's shot cleared.
constexpr uint32_t kDustShowcaseTick = 1240;

TEST_F(ShowcaseTest, DustyCratesFillTheirCheckpoint) {
    expect_showcase(effect_share("harbour_dust", kDustShowcaseTick, skipping(kDustPass)));
}

// An amount that shows as a coat of dust (the shells fade in from 0.08 to 0.85), and one
// under which they draw nothing.
constexpr float kCoat = 0.4f;
constexpr float kBare = 0.08f;
// Every pixel's point on a prop has sim vertices (8 cm apart) this near.
constexpr float kVertexReachM = 0.1f;

// The pixels that show a dusty prop's surface where a coat lay and the sim has blown it
// all off (`cleared`), and where a coat still lies (`dusty`). Each pixel's point on the
// props comes from the depth of a frame drawn without dust; it counts only if every dust
// vertex within kVertexReachM of it agrees (so no edge, side or fading rim is counted).
struct DustPixels {
    std::vector<size_t> cleared, dusty;
};

DustPixels dust_pixels(RenderStage& stage, const sim::CameraView& view, const std::vector<float>& depth,
                       const std::vector<float>& at_start) {
    const sim::DustField& dust = stage.world().get<sim::DustField>();
    const std::vector<glm::vec3>& positions = dust.surface().positions();
    const std::span<const float> now = dust.amounts();
    auto cell = [](glm::vec3 p) { return glm::ivec3(glm::floor(p / kVertexReachM)); };
    auto key = [](glm::ivec3 c) {
        return (uint64_t(uint32_t(c.x) & 0x1fffffu) << 42) | (uint64_t(uint32_t(c.y) & 0x1fffffu) << 21) |
               uint64_t(uint32_t(c.z) & 0x1fffffu);
    };
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
    for (uint32_t v = 0; v < positions.size(); ++v) cells[key(cell(positions[v]))].push_back(v);

    const effects::Camera camera = stage.camera(view);
    const int w = stage.width(), h = stage.height();
    DustPixels out;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            if (depth[i] >= 1.0f) continue;
            const glm::vec4 ndc((float(x) + 0.5f) / float(w) * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / float(h) * 2.0f,
                                depth[i] * 2.0f - 1.0f, 1.0f);
            const glm::vec4 q = camera.inv_view_proj * ndc;
            const glm::vec3 p = glm::vec3(q) / q.w;
            bool near = false, cleared = true, dusty = true;
            const glm::ivec3 c = cell(p);
            for (int dz = -1; dz <= 1; ++dz)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const auto found = cells.find(key(c + glm::ivec3(dx, dy, dz)));
                        if (found == cells.end()) continue;
                        for (uint32_t v : found->second) {
                            if (glm::distance(positions[v], p) > kVertexReachM) continue;
                            near = true;
                            cleared = cleared && at_start[v] >= kCoat && now[v] <= kBare;
                            dusty = dusty && now[v] >= kCoat;
                        }
                    }
            if (near && cleared) out.cleared.push_back(i);
            if (near && dusty) out.dusty.push_back(i);
        }
    return out;
}

int median_change(const game::ImageRGBA8& a, const game::ImageRGBA8& b, const std::vector<size_t>& pixels) {
    std::vector<int> changes;
    for (size_t i : pixels) changes.push_back(pixel_change(a, b, i));
    if (changes.empty()) return -1;
    std::nth_element(changes.begin(), changes.begin() + ptrdiff_t(changes.size() / 2), changes.end());
    return changes[changes.size() / 2];
}

// At the showcase checkpoint the patch the shot blew off a crate's top shows the bare
// crate: over it the frame barely changes without the dust pass, over the coat around
// it a lot. The patch and the coat are where the sim's amounts say, not chosen pixels.
TEST_F(ShowcaseTest, TheShotsClearedPatchShowsTheBareCrate) {
    Checkpoint c = replay_to("harbour_dust", kDustShowcaseTick);
    RenderStage& stage = *c.stage;
    const game::ImageRGBA8 bare = stage.render(c.view, {.skip = kDustPass, .time_s = c.time_s});
    const std::vector<float> depth = stage.depth();
    const game::ImageRGBA8 dusty = stage.render(c.view, {.time_s = c.time_s});
    const DustPixels pixels = dust_pixels(stage, c.view, depth, c.dust_at_start);
    const int over_patch = median_change(dusty, bare, pixels.cleared);
    const int over_coat = median_change(dusty, bare, pixels.dusty);
    std::printf("cleared patch: %zu pixels, median change %d/255; dusty: %zu pixels, median change %d/255\n",
                pixels.cleared.size(), over_patch, pixels.dusty.size(), over_coat);
    if (std::getenv("SPINDRIFT_SHOWCASE_PNG_DIR")) {
        game::ImageRGBA8 marked = dusty;  // the patch red, the coat blue
        for (size_t i : pixels.cleared) marked.pixels[i * 4] = 255;
        for (size_t i : pixels.dusty) marked.pixels[i * 4 + 2] = 255;
        maybe_write(marked, "harbour_dust_patch");
    }
    ASSERT_GE(pixels.cleared.size(), 100u) << "no patch the shot cleared is in view";
    ASSERT_GE(pixels.dusty.size(), 100u) << "no dust around the patch is in view";
    EXPECT_LE(over_patch, 10) << "the cleared patch should show the bare crate";
    EXPECT_GE(over_coat, 20) << "the dust around the patch should show";
}

// Rain on the windshield from the driver's seat, parked with the wipers off.
TEST_F(ShowcaseTest, RainOnTheGlassFillsItsCheckpoint) {
    expect_showcase(effect_share("harbour_rain", 1690, skipping(kRainPass)));
}

}  // namespace
