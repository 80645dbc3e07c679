// replays/harbour_boat.script: its checkpoint frames are meant to catch the splashes
// its comment names. Runs the script's sim (no rendering) and checks which splash is
// in the air at each checkpoint, so a retimed throw or a changed splash shows up here
// rather than in a frame nobody looked at.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "game/level/LevelLoader.h"
#include "game/replay/InputScript.h"
#include "sim/player/Player.h"
#include "sim/vehicle/Boat.h"
#include "sim/water/WaterSim.h"
#include "sim/world/World.h"

namespace {

// What started the splash on one sheet: a stone's first or second, or a float's first.
enum class Splash { StoneFirst, StoneSecond, FloatFirst };

struct SheetSplash {
    Splash kind;
    uint32_t started_tick;
};

std::string name(Splash s) {
    switch (s) {
        case Splash::StoneFirst: return "stone first";
        case Splash::StoneSecond: return "stone second";
        case Splash::FloatFirst: return "float first";
    }
    return "?";
}

TEST(HarbourBoatScript, CheckpointsCatchTheSplashesTheyName) {
    const game::InputScript script =
        game::load_script(std::string(SPINDRIFT_TEST_DATA) + "/../../replays/harbour_boat.script");
    sim::World world(game::load_level(script.level).sim);
    const sim::WaterSim& water = world.get<sim::WaterSim>();
    // Per checkpoint, the splash it is there for, and at most how many ticks after that
    // splash started the frame may come (the crown is short-lived; the jet takes a
    // moment to rise into a column before its top breaks into drops).
    const std::map<uint32_t, std::pair<Splash, uint32_t>> wanted = {
        {682, {Splash::StoneFirst, 12}}, {703, {Splash::StoneSecond, 16}}, {796, {Splash::FloatFirst, 8}},
        {941, {Splash::StoneFirst, 12}}, {962, {Splash::StoneSecond, 16}},
    };
    for (const auto& [tick, _] : wanted)
        ASSERT_NE(std::find(script.checkpoints.begin(), script.checkpoints.end(), tick), script.checkpoints.end())
            << "checkpoint " << tick << " is not in the script";

    std::vector<SheetSplash> on_sheet(water.sheets().size(), {Splash::StoneFirst, 0});
    std::vector<bool> started(water.sheets().size(), false);
    for (uint32_t t = 0; t < script.end_tick; ++t) {
        world.step(script.inputs[t]);
        // First splashes come in the order of this tick's water entries.
        size_t entry = 0;
        for (const sim::SplashEvent& e : water.splashes()) {
            Splash kind = Splash::StoneSecond;
            if (e.kind == sim::SplashEvent::Kind::First) {
                ASSERT_LT(entry, world.events().water_entries.size());
                kind = world.events().water_entries[entry++].sinks ? Splash::StoneFirst : Splash::FloatFirst;
            }
            on_sheet[size_t(e.sheet)] = {kind, t};
            started[size_t(e.sheet)] = true;
        }
        if (water.bow_sheet() >= 0) started[size_t(water.bow_sheet())] = false;  // bow spray, not a throw
        auto w = wanted.find(t);
        if (w == wanted.end()) continue;
        const auto [kind, within] = w->second;
        std::string seen;
        bool caught = false;
        for (size_t k = 0; k < water.sheets().size(); ++k) {
            if (!started[k] || water.sheets()[k].airborne_count() == 0) continue;
            seen.append(" ").append(name(on_sheet[k].kind)).append(" from ").append(std::to_string(on_sheet[k].started_tick));
            caught = caught || (on_sheet[k].kind == kind && t - on_sheet[k].started_tick <= within);
        }
        EXPECT_TRUE(caught) << "checkpoint " << t << " wants a " << name(kind) << " splash at most " << within
                            << " ticks old; in the air:" << (seen.empty() ? " nothing" : seen);
    }
}

// The wake's checkpoint: the boat at speed (at least 18 km/h), seen from the chase
// camera, with the wake it pushes behind it.
TEST(HarbourBoatScript, TheWakeCheckpointCatchesTheBoatAtSpeedFromTheChaseCamera) {
    constexpr uint32_t kWake = 470;
    const game::InputScript script =
        game::load_script(std::string(SPINDRIFT_TEST_DATA) + "/../../replays/harbour_boat.script");
    ASSERT_NE(std::find(script.checkpoints.begin(), script.checkpoints.end(), kWake), script.checkpoints.end())
        << "checkpoint " << kWake << " is not in the script";
    sim::World world(game::load_level(script.level).sim);
    for (uint32_t t = 0; t <= kWake; ++t) world.step(script.inputs[t]);
    const sim::Player& player = world.get<sim::Player>();
    EXPECT_EQ(player.vehicle(), sim::Vehicle::Boat);
    EXPECT_EQ(player.view(), sim::ViewMode::Chase);
    const sim::Boat& boat = world.get<sim::Boat>();
    EXPECT_GT(boat.speed_mps(), 5.0f);
    // The wake: behind the stern the water is well off its rest level, ahead of the bow
    // it is calm (the greatest departure over 12 m by 12 m on either side).
    const sim::WaterSim& water = world.get<sim::WaterSim>();
    const glm::vec3 fwd = boat.pose().forward_flat(), right = boat.pose().right_flat();
    auto roughest = [&](float from_m, float to_m) {
        float most = 0.0f;
        for (float along = from_m; along <= to_m; along += 0.5f)
            for (float across = -6.0f; across <= 6.0f; across += 0.5f) {
                const glm::vec3 p = boat.pose().position + fwd * along + right * across;
                most = std::max(most, std::abs(water.height_at({p.x, p.z}) - water.sea_level()));
            }
        return most;
    };
    const float half = 0.5f * boat.params().length_m;
    const float behind = roughest(-half - 12.0f, -half), ahead = roughest(half + 2.0f, half + 14.0f);
    EXPECT_GT(behind, 0.02f);
    EXPECT_GT(behind, 3.0f * ahead) << "behind " << behind << " m, ahead " << ahead << " m";
}

}  // namespace
