// Seeking in a replay (game/replay/ReplaySeeker.h, KeyframeStore.h): keyframes are kept
// as the replay is stepped, a seek anywhere lands on the world the recording had at that
// tick (its recorded hash), a step back re-simulates only from the nearest raw snapshot,
// and the compressed keyframes are smaller than the snapshots.
#include <string>

#include <gtest/gtest.h>

#include "game/level/LevelLoader.h"
#include "game/replay/KeyframeStore.h"
#include "game/replay/ReplayReader.h"
#include "game/replay/ReplaySeeker.h"
#include "game/session/GameSession.h"

namespace {

struct Watched {
    game::Replay replay = game::read_replay(std::string(SPINDRIFT_TEST_DATA) + "/../../replays/harbour_goals.replay",
                                            game::ReadOptions{true});
    game::GameSession session = game::GameSession::start(game::load_level("harbour"), 1, replay.header.seed);
    game::KeyframeStore keyframes{session.level.content_hash, 300};
    game::ReplaySeeker seeker{replay.inputs, *session.world, keyframes, 30};

    uint64_t recorded(uint64_t tick) const { return replay.tick_world_hashes[size_t(tick) - 1]; }
    uint64_t now() const { return session.world->hash().world; }
};

}  // namespace

TEST(ReplaySeek, ASeekAnywhereReachesTheRecordedWorld) {
    Watched w;
    ASSERT_GT(w.seeker.ticks(), 1500u);
    EXPECT_EQ(w.keyframes.count(), 1u) << "tick 0's";
    // Forwards the first time: stepped, keyframes kept on the way.
    EXPECT_EQ(w.seeker.seek(1631), 1631u);
    EXPECT_EQ(w.now(), w.recorded(1631));
    EXPECT_EQ(w.keyframes.count(), 6u) << "ticks 0, 300, ..., 1500";
    // Back, from the keyframe at or before: at most 299 ticks re-simulated.
    EXPECT_EQ(w.seeker.seek(505), 205u) << "from the keyframe at 300";
    EXPECT_EQ(w.now(), w.recorded(505));
    EXPECT_EQ(w.seeker.seek(1), 1u);
    EXPECT_EQ(w.now(), w.recorded(1));
    // Forwards past a keyframe: restored from it rather than stepped all the way.
    EXPECT_EQ(w.seeker.seek(1560), 60u);
    EXPECT_EQ(w.now(), w.recorded(1560));
    EXPECT_EQ(w.seeker.seek(w.seeker.ticks() + 100), w.seeker.ticks() - 1560) << "clamped to the end";
    EXPECT_EQ(w.now(), w.recorded(w.seeker.ticks()));
}

TEST(ReplaySeek, OneTickBackReSimulatesFromTheNearestRawSnapshot) {
    Watched w;
    w.seeker.seek(700);
    for (uint64_t t = 700; t > 640; --t) {
        const uint64_t simulated = w.seeker.seek(t - 1);
        EXPECT_LT(simulated, 30u) << "to tick " << t - 1;
        ASSERT_EQ(w.now(), w.recorded(t - 1)) << "tick " << t - 1;
    }
    EXPECT_GT(w.seeker.near_bytes(), 0u);
    // Stepping on from there plays the recording.
    for (int i = 0; i < 5; ++i) ASSERT_TRUE(w.seeker.step());
    EXPECT_EQ(w.now(), w.recorded(645));
}

TEST(ReplaySeek, KeyframesAreCompressed) {
    Watched w;
    w.seeker.seek(w.seeker.ticks());
    EXPECT_EQ(w.keyframes.count(), w.seeker.ticks() / 300 + 1);
    EXPECT_LT(w.keyframes.compressed_bytes() * 4, w.keyframes.raw_bytes());
    EXPECT_EQ(*w.keyframes.at_or_before(0), 0u);
    EXPECT_EQ(*w.keyframes.at_or_before(899), 600u);
    EXPECT_THROW(game::KeyframeStore(1, 0), std::invalid_argument);
}
