// The replay checker: a faithful replay passes every tick; a desync is named by its first
// tick and subsystem, whatever kind of recorded hash disagrees; another simulation is refused.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ReplayFile.h"
#include "SimTestLevel.h"
#include "game/replay/ReplayCheck.h"
#include "game/replay/ReplayReader.h"
#include "game/replay/ReplayWriter.h"

namespace {

using replay_test::ReplayFile;
using replay_test::test_header;
namespace fs = std::filesystem;

// A session in a real world: drives, steers and fires, so every subsystem has state.
std::vector<sim::TickInput> drive_inputs(uint32_t ticks) {
    std::vector<sim::TickInput> inputs(ticks);
    for (uint32_t t = 0; t < ticks; ++t) {
        inputs[t].set(sim::Control::Throttle, t % 50 < 35);
        inputs[t].set(sim::Control::SteerLeft, t % 40 >= 30);
        inputs[t].set(sim::Control::Fire, t % 70 == 10);
    }
    return inputs;
}

// Records `inputs` as the record command does and reads the file back.
game::Replay record_test_world(const fs::path& path, const std::vector<sim::TickInput>& inputs) {
    sim::World world(make_test_level());
    game::ReplayHeader h = test_header();
    h.subsystem_names = world.subsystem_names();
    h.sim_signature = world.sim_signature();
    auto writer = game::ReplayWriter::create(path, h);
    for (sim::TickInput in : inputs) {
        world.step(in);
        writer.append(in, world.hash());
    }
    writer.finish();
    return game::read_replay(path);
}

struct CheckOutcome {
    std::optional<game::Divergence> divergence;
    size_t checked = 0;
};

// Replays `inputs` into a fresh world, checking every tick against `r`, up to the first divergence.
CheckOutcome check_test_world(const game::Replay& r, const std::vector<sim::TickInput>& inputs) {
    sim::World world(make_test_level());
    game::ReplayChecker checker(r);
    CheckOutcome out;
    for (sim::TickInput in : inputs) {
        world.step(in);
        if ((out.divergence = checker.after_step(world))) break;
    }
    out.checked = checker.hashes_checked();
    return out;
}

class ReplayCheck : public ReplayFile {
protected:
    const std::vector<sim::TickInput> inputs_ = drive_inputs(150);
};

TEST_F(ReplayCheck, PassesAFaithfulReplayCheckingEveryTick) {
    const game::Replay r = record_test_world(file("w.replay"), inputs_);
    ASSERT_EQ(r.tick_world_hashes.size(), 150u);
    ASSERT_EQ(r.header.subsystem_names[0], "player");
    ASSERT_EQ(r.hashes.size(), 3u);  // chunk ends at ticks 60, 120, 150
    CheckOutcome out = check_test_world(r, inputs_);
    EXPECT_FALSE(out.divergence) << out.divergence->message;
    EXPECT_EQ(out.checked, 150u);
    std::vector<sim::TickInput> longer = inputs_;  // ticks past the recording hold nothing to check
    longer.resize(170);
    out = check_test_world(r, longer);
    EXPECT_FALSE(out.divergence) << out.divergence->message;
    EXPECT_EQ(out.checked, 150u);
}

// The header's simulation signature (the sim's version and subsystem names) must be
// this world's: another is refused before any tick, naming it.
TEST_F(ReplayCheck, RefusesAnotherSimulationSignatureNamingIt) {
    game::Replay r = record_test_world(file("w.replay"), inputs_);
    const sim::World world(make_test_level());
    const uint64_t level_hash = r.header.level_hash;
    EXPECT_FALSE(game::replay_mismatch(r, world, level_hash));
    r.header.sim_signature ^= 1;
    const std::optional<std::string> m = game::replay_mismatch(r, world, level_hash);
    ASSERT_TRUE(m);
    EXPECT_NE(m->find("recorded by a different simulation (simulation signature "), std::string::npos) << *m;
    EXPECT_NE(m->find("re-record it from its .script"), std::string::npos) << *m;
}

TEST_F(ReplayCheck, NamesTheFirstDivergingTickAndSubsystem) {
    const game::Replay r = record_test_world(file("w.replay"), inputs_);
    std::vector<sim::TickInput> changed = inputs_;
    changed[100].held ^= uint16_t(sim::Control::Throttle);  // applied by the step to tick 101
    const CheckOutcome out = check_test_world(r, changed);
    ASSERT_TRUE(out.divergence);
    EXPECT_EQ(out.divergence->tick, 101u);
    EXPECT_EQ(out.checked, 101u);
    const std::string& m = out.divergence->message;
    EXPECT_EQ(m.rfind("tick 101: world hash ", 0), 0u) << m;
    char recorded[24];
    std::snprintf(recorded, sizeof recorded, "%016llx", static_cast<unsigned long long>(r.tick_world_hashes[100]));
    EXPECT_NE(m.find(std::string(" differs from the recorded ") + recorded + "; subsystem 'player' differs first"),
              std::string::npos)
        << m;
}

TEST_F(ReplayCheck, ReportsEveryKindOfRecordedHashThatDisagrees) {
    const game::Replay r = record_test_world(file("w.replay"), inputs_);
    const size_t parts = r.header.subsystem_names.size();
    auto expect_divergence = [&](const game::Replay& damaged, uint32_t tick, const std::string& ending) {
        const CheckOutcome out = check_test_world(damaged, inputs_);
        ASSERT_TRUE(out.divergence) << ending;
        EXPECT_EQ(out.divergence->tick, tick);
        const std::string& m = out.divergence->message;
        EXPECT_TRUE(m.size() >= ending.size() && m.compare(m.size() - ending.size(), ending.size(), ending) == 0)
            << m << "\ndoes not end with: " << ending;
    };
    game::Replay d = r;  // a world hash whose parts all match
    d.tick_world_hashes[29] ^= 1;
    expect_divergence(d, 30, "; no subsystem fingerprint differs at this tick");
    d = r;  // the same at a chunk's end, where the full parts are compared
    d.tick_world_hashes[59] ^= 1;
    expect_divergence(d, 60, "; no subsystem hash differs at this tick");
    d = r;
    d.hashes[1].hash.parts[2] ^= 1ull << 40;  // a full part hash that the fingerprint cannot see
    expect_divergence(d, 120, "matches the recording but the subsystem hashes recorded at this chunk's end do not; "
                              "subsystem '" + r.header.subsystem_names[2] + "' differs first");
    d = r;
    d.tick_fingerprints[44 * parts + 3] ^= 1;
    d.tick_fingerprints[44 * parts + 1] ^= 1;
    expect_divergence(d, 45, "matches the recording but the recorded subsystem fingerprints do not; subsystem '" +
                                 r.header.subsystem_names[1] + "' differs first (then: " +
                                 r.header.subsystem_names[3] + ")");
}


}  // namespace
