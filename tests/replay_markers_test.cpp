// The viewer's timeline markers (game/replay/ReplayMarkers.h) on replays/harbour_goals:
// the shot that lights the crate, the hits, the switch into the boat, the boat's lap.
#include <string>

#include <gtest/gtest.h>

#include "game/level/LevelLoader.h"
#include "game/replay/ObjectiveSummary.h"
#include "game/replay/ReplayMarkers.h"
#include "game/replay/ReplayReader.h"
#include "sim/world/World.h"

namespace {

bool has(const game::ReplayMarkers& m, uint64_t tick, game::MarkerKind kind, const std::string& label = "") {
    for (const game::ReplayMarker& x : m.markers())
        if (x.tick == tick && x.kind == kind && (label.empty() || x.label == label)) return true;
    return false;
}

}  // namespace

TEST(ReplayMarkers, MarkTheGoalsReplaysMoments) {
    const game::Replay replay = game::read_replay(
        std::string(SPINDRIFT_TEST_DATA) + "/../../replays/harbour_goals.replay", game::ReadOptions{true});
    sim::World world(game::load_level("harbour", nullptr).sim);
    game::ReplayMarkers markers;
    for (const sim::TickInput& in : replay.inputs) {
        world.step(in);
        markers.after_tick(world);
    }
    using K = game::MarkerKind;
    EXPECT_TRUE(has(markers, 463, K::Shot)) << "the script taps fire at 462";
    EXPECT_TRUE(has(markers, 499, K::TargetHit, "1 target hit")) << "the crate, by the shot";
    EXPECT_TRUE(has(markers, 523, K::VehicleSwitch, "into the boat"));
    EXPECT_TRUE(has(markers, 1631, K::TargetHit, "2 targets hit")) << "the buoy, by the stone";
    size_t laps = 0, gates = 0;
    for (const game::ReplayMarker& m : markers.markers()) {
        laps += m.kind == K::Lap;
        gates += m.kind == K::Gate;
        if (m.kind == K::Lap) {
            EXPECT_EQ(m.label, "lap 1 of pier, " + game::lap_time_text(816));
        }
    }
    EXPECT_EQ(laps, 1u);
    EXPECT_GE(gates, 4u) << "the boat's gates before the lap";

    ASSERT_TRUE(markers.next_after(499).has_value());
    EXPECT_GT(markers.next_after(499)->tick, 499u);
    EXPECT_EQ(markers.previous_before(500)->tick, 499u);
    EXPECT_FALSE(markers.previous_before(markers.markers().front().tick).has_value());
    EXPECT_FALSE(markers.next_after(markers.markers().back().tick).has_value());
}
