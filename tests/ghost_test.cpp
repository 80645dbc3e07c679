// The ghost to race (play --ghost, game/play/GhostRace.h): its world steps with the
// replay's inputs in lockstep with the live one, so its vehicle is where the replay had
// it at every tick; the gap at each gate counts the ticks between the two passes; the
// ghost pass draws it see-through and nothing when there is none.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "HeadlessTest.h"
#include "effects/Renderer.h"
#include "game/capture/FrameCapture.h"
#include "game/play/GhostHud.h"
#include "game/play/GhostRace.h"
#include "game/replay/ReplayReader.h"
#include "game/session/GameSession.h"
#include "sim/player/Player.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"

namespace {

game::Replay bundled(const char* name) {
    return game::read_replay(std::string(SPINDRIFT_DATA_DIR) + "/replays/" + name + ".replay", game::ReadOptions{});
}

bool same_bits(const sim::Pose& a, const sim::Pose& b) { return std::memcmp(&a, &b, sizeof(sim::Pose)) == 0; }

// The live world drives the replay's own inputs: the ghost is the replay's world, so at
// every tick its vehicle (car, then the boat once the replay switches) has the pose the
// live one has, to the bit, and its world the hash the file recorded.
TEST(Ghost, ItsPoseAtEveryTickIsTheReplays) {
    const game::Replay replay = bundled("harbour_goals");
    game::GameSession live = game::GameSession::open(replay.header.level_id, 1, replay.header.seed);
    game::GhostRace race(replay, "harbour_goals", live.level.sim, 1);
    bool saw_boat = false;
    for (size_t i = 0; i < replay.inputs.size(); ++i) {
        live.world->step(sim::quantise(replay.inputs[i]));
        race.after_live_tick(*live.world);
        const uint64_t tick = live.world->tick();
        ASSERT_EQ(race.world().tick(), tick);
        const sim::Vehicle vehicle = live.world->get<sim::Player>().vehicle();
        const effects::FramePoses::Ghost ghost = race.pose();
        ASSERT_EQ(ghost.vehicle, vehicle) << "tick " << tick;
        const sim::Pose& want =
            vehicle == sim::Vehicle::Car ? live.world->get<sim::Car>().pose() : live.world->get<sim::Boat>().pose();
        ASSERT_TRUE(same_bits(ghost.pose, want)) << "tick " << tick;
        saw_boat = saw_boat || vehicle == sim::Vehicle::Boat;
        if (tick % 60 == 0) {
            ASSERT_EQ(race.world().hash().world, replay.tick_world_hashes[i]) << "tick " << tick;
        }
    }
    EXPECT_TRUE(saw_boat) << "the replay takes the boat round its course";
    EXPECT_TRUE(race.finished());
    // Every gate both passed, at the same ticks.
    ASSERT_FALSE(race.gaps().empty());
    for (const game::GateGap& g : race.gaps()) EXPECT_EQ(g.gap_ticks, 0) << g.course << " gate " << g.gate;
    // Past its end the ghost waits where the replay stopped.
    const sim::Pose last = race.pose().pose;
    for (int i = 0; i < 30; ++i) {
        live.world->step({});
        race.after_live_tick(*live.world);
    }
    EXPECT_TRUE(same_bits(race.pose().pose, last));
}

// The player drives the ghost's line 45 ticks late: every gate is passed 45 ticks
// (0.75 s) after the ghost, the start included; a restart starts the ghost again.
TEST(Ghost, TheGapAtEachGateIsTheTicksBetweenThePasses) {
    constexpr size_t kLate = 45;
    const game::Replay replay = bundled("harbour_drive");
    game::GameSession live = game::GameSession::open(replay.header.level_id, 1, replay.header.seed);
    game::GhostRace race(replay, "harbour_drive", live.level.sim, 1);
    for (size_t t = 0; t < replay.inputs.size() + kLate; ++t) {
        live.world->step(t < kLate ? sim::TickInput{} : sim::quantise(replay.inputs[t - kLate]));
        race.after_live_tick(*live.world);
    }
    ASSERT_EQ(race.gaps().size(), 6u) << "the quay course's five gates and the finish";
    for (size_t n = 0; n < race.gaps().size(); ++n) {
        const game::GateGap& g = race.gaps()[n];
        EXPECT_EQ(g.course, "quay");
        EXPECT_EQ(g.gate, n % 5);
        EXPECT_EQ(g.lap, n == 0 ? 0u : 1u);
        EXPECT_EQ(g.gap_ticks, int64_t(kLate)) << "pass " << n;
    }
    EXPECT_EQ(game::ghost_hud_lines(race).back(), "quay finish of lap 1  +0.75 s");

    live.world = std::make_unique<sim::World>(live.level.sim, sim::WorldOptions{1});
    race.restart();
    EXPECT_EQ(race.world().tick(), 0u);
    EXPECT_TRUE(race.gaps().empty());
}

TEST(Ghost, GapsReadAsTimeTrialsShowThem) {
    EXPECT_EQ(game::gap_text(45), "+0.75 s");
    EXPECT_EQ(game::gap_text(-63), "-1.05 s");
    EXPECT_EQ(game::gap_text(0), "0.00 s");
    EXPECT_EQ(game::gap_text(1), "+0.02 s");
}

class GhostRender : public HeadlessTest {};

// The ghost car beside the player's, seen from the chase camera: drawn where it stands,
// see-through (no pixel of it as far from what is behind as an opaque car would be),
// and a frame without a ghost is the frame it always was.
TEST_F(GhostRender, TheGhostIsDrawnSeeThroughAndOnlyWhenThereIsOne) {
    game::GameSession s = game::GameSession::open("harbour", 1);
    sim::TickInput throttle;
    throttle.set(sim::Control::Throttle, true);
    for (int t = 0; t < 90; ++t) s.world->step(throttle);
    effects::Renderer renderer(s.level.scene, *s.world);
    game::FrameCapture capture(320, 180);
    effects::FramePoses poses = effects::capture_poses(*s.world);
    renderer.render(*s.world, capture.output(), poses);
    const game::ImageRGBA8 without = capture.read();
    renderer.render(*s.world, capture.output(), poses);
    const game::ImageRGBA8 again = capture.read();
    EXPECT_EQ(without.pixels, again.pixels);

    sim::Pose ahead = poses.car;
    // Beside the player's car, a lane to its left and a little ahead.
    const float h = ahead.heading_rad;
    ahead.position += 3.0f * glm::vec3(std::cos(h), 0.0f, -std::sin(h)) + 3.5f * glm::vec3(-std::sin(h), 0.0f, -std::cos(h));
    poses.ghost = effects::FramePoses::Ghost{sim::Vehicle::Car, ahead};
    renderer.render(*s.world, capture.output(), poses);
    const game::ImageRGBA8 with = capture.read();
    size_t changed = 0, opaque_like = 0;
    for (size_t i = 0; i < with.pixels.size(); i += 4) {
        int diff = 0;
        for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(int(with.pixels[i + c]) - int(without.pixels[i + c])));
        if (diff > 8) ++changed;
        if (diff > 200) ++opaque_like;
    }
    const size_t pixels = with.pixels.size() / 4;
    EXPECT_GT(changed, pixels / 200) << "the ghost covers part of the road beside the car";
    EXPECT_LT(changed, pixels / 4);
    EXPECT_LT(opaque_like, changed / 10) << "see-through: the road shows through it";
}

}  // namespace
