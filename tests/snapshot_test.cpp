// World snapshots (docs/REPLAYS.md, "Snapshots"): a world restored from a snapshot into
// a fresh world steps on with the original's hashes, tick for tick; a snapshot of
// another sim or level, or a damaged one, is refused with a message saying why. The
// same over every bundled replay is `spindrift-check --snapshots 300` (ctest
// replay_snapshots).
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ErrorMessage.h"
#include "SimInput.h"
#include "SimTestLevel.h"
#include "sim/core/StateArchive.h"
#include "sim/rain/GlassSurface.h"
#include "sim/world/World.h"

namespace {

using sim::Control;

constexpr uint64_t kLevelHash = 0x1234abcdull;

// Water, rain glass and a tank, so most subsystems have state to carry.
sim::LevelDesc busy_level() {
    sim::LevelDesc level = make_test_level();
    level.water.enabled = true;
    sim::GlassSurface::flat_edges(1.4f, 0.8f, 0.76f, level.rain.glass_lower, level.rain.glass_upper);
    level.rain_intensity = 1.0f;
    level.fluid.enabled = true;
    level.fluid.particle_count = 300;
    level.tank_spot = {-10.0f, 1.0f, -30.0f};
    return level;
}

// Driving, throwing, firing and wiping: input that changes with the tick.
sim::TickInput input_at(uint64_t t) {
    sim::TickInput in = held({Control::Throttle});
    in.set(Control::SteerLeft, (t / 40) % 2 == 0);
    in.set(Control::ThrowHeavy, t % 50 == 10);
    in.set(Control::ThrowLight, t % 70 == 20);
    in.set(Control::Fire, t % 60 == 30);
    in.set(Control::Wipers, t == 5);
    return in;
}

void step_to(sim::World& w, uint64_t tick) {
    while (w.tick() < tick) w.step(input_at(w.tick()));
}

}  // namespace

TEST(Snapshot, ARestoredWorldStepsOnWithTheOriginalsHashes) {
    sim::World original(busy_level());
    const std::vector<std::string> names = original.subsystem_names();
    for (const char* name : {"water", "rain", "fluid", "weapon", "objects"})
        ASSERT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    step_to(original, 150);
    const std::vector<uint8_t> snap = original.snapshot(kLevelHash);

    sim::World fresh(busy_level());
    ASSERT_NE(fresh.hash(), original.hash());
    EXPECT_EQ(fresh.restore_generation(), 0u);
    fresh.restore(snap, kLevelHash);
    EXPECT_EQ(fresh.restore_generation(), 1u) << "presentation caches see that the world was replaced";
    EXPECT_EQ(fresh.tick(), 150u);
    EXPECT_EQ(fresh.last_input(), original.last_input());
    EXPECT_EQ(fresh.hash(), original.hash());
    for (int i = 0; i < 120; ++i) {
        original.step(input_at(original.tick()));
        fresh.step(input_at(fresh.tick()));
        ASSERT_EQ(fresh.hash(), original.hash()) << "at tick " << fresh.tick();
    }
    EXPECT_EQ(fresh.snapshot(kLevelHash), original.snapshot(kLevelHash)) << "unhashed state too";
}

TEST(Snapshot, RestoringAnEarlierSnapshotGoesBackInTime) {
    sim::World w(busy_level());
    step_to(w, 60);
    const std::vector<uint8_t> at60 = w.snapshot(kLevelHash);
    const sim::WorldHash h60 = w.hash();
    step_to(w, 200);
    const sim::WorldHash h200 = w.hash();
    w.restore(at60, kLevelHash);
    EXPECT_EQ(w.hash(), h60);
    step_to(w, 200);
    EXPECT_EQ(w.hash(), h200);
}

TEST(Snapshot, AnotherSimVersionIsRefused) {
    sim::World w(busy_level());
    step_to(w, 30);
    std::vector<uint8_t> snap = w.snapshot(kLevelHash);
    uint64_t signature;
    std::memcpy(&signature, snap.data() + 12, 8);  // after the magic and the format
    ASSERT_EQ(signature, w.sim_signature());
    signature ^= 1;  // as another kSimVersion would make it
    std::memcpy(snap.data() + 12, &signature, 8);

    sim::World fresh(busy_level());
    const sim::WorldHash before = fresh.hash();
    const std::string message = message_of<sim::SnapshotError>([&] { fresh.restore(snap, kLevelHash); });
    EXPECT_NE(message.find("another simulation"), std::string::npos) << message;
    EXPECT_NE(message.find("sim version"), std::string::npos) << message;
    EXPECT_EQ(fresh.hash(), before) << "a refused snapshot leaves the world alone";
    EXPECT_EQ(fresh.restore_generation(), 0u);
}

TEST(Snapshot, AWorldOfOtherSubsystemsRefusesIt) {
    sim::World w(busy_level());
    sim::World fewer(busy_level(), sim::standard_subsystems({"player", "car", "boat", "camera"}));
    const std::string message = message_of<sim::SnapshotError>([&] { fewer.restore(w.snapshot(kLevelHash), kLevelHash); });
    EXPECT_NE(message.find("another simulation"), std::string::npos) << message;
}

TEST(Snapshot, AnotherLevelIsRefused) {
    sim::World w(busy_level());
    step_to(w, 30);
    sim::World fresh(busy_level());
    const std::string message =
        message_of<sim::SnapshotError>([&] { fresh.restore(w.snapshot(kLevelHash), kLevelHash + 1); });
    EXPECT_NE(message.find("another level"), std::string::npos) << message;
    EXPECT_NE(message.find("'test'"), std::string::npos) << message;
    EXPECT_EQ(fresh.tick(), 0u);
}

TEST(Snapshot, ACutOrPaddedSnapshotIsRefused) {
    sim::World w(busy_level());
    step_to(w, 30);
    const std::vector<uint8_t> snap = w.snapshot(kLevelHash);
    for (size_t keep : {size_t(4), size_t(40), snap.size() / 2, snap.size() - 1}) {
        std::vector<uint8_t> cut(snap.begin(), snap.begin() + long(keep));
        sim::World fresh(busy_level());
        EXPECT_THROW(fresh.restore(cut, kLevelHash), sim::SnapshotError) << "cut to " << keep << " bytes";
    }
    std::vector<uint8_t> padded = snap;
    padded.push_back(0);
    sim::World fresh(busy_level());
    const std::string message = message_of<sim::SnapshotError>([&] { fresh.restore(padded, kLevelHash); });
    EXPECT_NE(message.find("trailing"), std::string::npos) << message;
    std::vector<uint8_t> not_one = snap;
    not_one[0] = 'X';
    EXPECT_NE(message_of<sim::SnapshotError>([&] { fresh.restore(not_one, kLevelHash); }).find("magic"),
              std::string::npos);
}

// The hashing archive feeds the Hasher what the hand-written hash functions fed it:
// runs of scalars through FNV-1a, bulk arrays as parts joined by hash_combine.
namespace {
struct Sample {
    float a = 1.5f;
    uint32_t b = 7;
    std::vector<float> bulk{1.0f, 2.0f, 3.0f};
    template <class Archive> void describe(Archive& ar) {
        ar.f32(a);
        ar.u32(b);
        ar.words(bulk, 9);
        ar.unhashed(a);
    }
};
}  // namespace

TEST(Snapshot, TheHashingArchiveFeedsTheBytesAHandWrittenHashWould) {
    Sample s;
    sim::Hasher h;
    h.f32(s.a);
    h.u32(s.b);
    const uint64_t by_hand = sim::hash_combine(h.value(), sim::hash_words(s.bulk.data(), s.bulk.size() * 4, 9));
    EXPECT_EQ(sim::hash_state(s), by_hand);

    std::vector<uint8_t> bytes;
    sim::StateWriter out(bytes);
    s.describe(out);
    Sample back;
    back.a = 0.0f;
    back.b = 0;
    back.bulk.clear();
    sim::StateReader in(bytes);
    back.describe(in);
    EXPECT_EQ(in.remaining(), 0u);
    EXPECT_EQ(back.a, s.a);
    EXPECT_EQ(back.b, s.b);
    EXPECT_EQ(back.bulk, s.bulk);
}
