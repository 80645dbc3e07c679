// Taking over a replay (game/replay/TakeOverRecording.h): a script-driven take over of
// replays/harbour_goals at tick 600 (in the boat), driven on for four seconds; the new
// file holds the old inputs up to the tick and the new ones after, and checks from
// tick 0 with `spindrift replay --check` like any recording.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "game/level/LevelLoader.h"
#include "game/replay/KeyframeStore.h"
#include "game/replay/ReplayReader.h"
#include "game/replay/ReplaySeeker.h"
#include "game/replay/TakeOverRecording.h"
#include "game/session/GameSession.h"

namespace fs = std::filesystem;

TEST(TakeOver, TheNewRecordingHoldsTheOldInputsThenTheNewAndChecks) {
    const game::Replay old = game::read_replay(
        std::string(SPINDRIFT_TEST_DATA) + "/../../replays/harbour_goals.replay", game::ReadOptions{true});
    game::GameSession session = game::GameSession::start(game::load_level("harbour", nullptr), 1, old.header.seed);
    game::KeyframeStore keyframes(session.level.content_hash);
    game::ReplaySeeker seeker(old.inputs, *session.world, keyframes);
    seeker.seek(900);
    seeker.seek(600);  // watched past it and back, as a viewer would

    const fs::path out = fs::temp_directory_path() / ("spindrift_take_over_" + std::to_string(::getpid()) + ".replay");
    game::TakeOverRecording recording(out, old, 600, session.world->level());
    sim::World& world = *session.world;
    for (int t = 0; t < 240; ++t) {
        sim::TickInput in;
        in.set(sim::Control::Throttle, true);
        in.set(sim::Control::SteerRight, t < 120);
        in.set(sim::Control::ThrowHeavy, t == 60);
        world.step(in);
        recording.append(sim::quantise(in), world);
    }
    recording.finish();

    const game::Replay taken = game::read_replay(out, game::ReadOptions{true});
    ASSERT_EQ(taken.inputs.size(), 840u);
    for (size_t t = 0; t < 600; ++t) ASSERT_EQ(taken.inputs[t], old.inputs[t]) << "tick " << t;
    EXPECT_EQ(taken.tick_world_hashes[599], old.tick_world_hashes[599]);
    EXPECT_NE(taken.tick_world_hashes[700], old.tick_world_hashes[700]) << "driven differently after the take over";
    for (uint32_t c : taken.header.checkpoints) EXPECT_LT(c, 600u);

    const std::string check = std::string(SPINDRIFT_BIN) + " replay " + out.string() +
                              " --headless --check --frames none > /dev/null 2>&1";
    EXPECT_EQ(std::system(check.c_str()), 0) << check;
    fs::remove(out);

    EXPECT_THROW(game::TakeOverRecording(out, old, old.inputs.size() + 1, session.world->level()), game::ReplayError);
    EXPECT_FALSE(fs::exists(game::partial_replay_path(out))) << "nothing written for a refused take over";
}
