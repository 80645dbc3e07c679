#include "game/replay/SnapshotCheck.h"

#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>

#include "game/replay/ReplayCheck.h"
#include "sim/core/StateArchive.h"
#include "sim/world/World.h"

namespace game {

namespace {

// The first subsystem whose saved state differs between two snapshots of one world's
// layout, or "the world's clock" when the header does.
std::string first_difference(const sim::World& world, const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    constexpr size_t kHeader = 8 + 4 + 8 + 8 + 8 + 5 + 4;  // sim/world/WorldSnapshot.cpp
    if (a.size() < kHeader || b.size() < kHeader || !std::equal(a.begin(), a.begin() + kHeader, b.begin()))
        return "the world's tick or last input";
    size_t at = kHeader;
    for (const std::string& name : world.subsystem_names()) {
        uint64_t na = 0, nb = 0;
        if (at + 8 > a.size() || at + 8 > b.size()) break;
        std::memcpy(&na, a.data() + at, 8);
        std::memcpy(&nb, b.data() + at, 8);
        if (na != nb || at + 8 + na > a.size() || !std::equal(a.begin() + long(at), a.begin() + long(at + 8 + na), b.begin() + long(at)))
            return "subsystem '" + name + "'";
        at += 8 + na;
    }
    return "their lengths";
}

}  // namespace

SnapshotCheckResult check_snapshots(const Replay& replay, const sim::LevelDesc& level, uint64_t level_hash,
                                    uint32_t every, int threads) {
    SnapshotCheckResult result;
    sim::World world(level, sim::WorldOptions{threads});
    ReplayChecker checker(replay);
    const size_t ticks = replay.inputs.size();
    std::vector<uint8_t> taken = world.snapshot(level_hash);
    for (size_t from = 0; from < ticks; from += every) {
        const size_t to = std::min(ticks, from + size_t(every));
        // The original world on to the next snapshot, checked as any replay is.
        for (size_t t = from; t < to; ++t) {
            world.step(replay.inputs[t]);
            if (auto d = checker.after_step(world)) {
                result.failure = "the replay itself desyncs at " + d->message;
                return result;
            }
        }
        const std::vector<uint8_t> next = world.snapshot(level_hash);
        result.largest_bytes = std::max(result.largest_bytes, taken.size());

        // A fresh world from the snapshot at `from`, stepped the same ticks.
        sim::World fresh(level, sim::WorldOptions{threads});
        fresh.restore(taken, level_hash);
        ++result.snapshots;
        ReplayChecker fresh_checker(replay);
        for (size_t t = from; t < to; ++t) {
            fresh.step(replay.inputs[t]);
            ++result.ticks_restepped;
            if (auto d = fresh_checker.after_step(fresh)) {
                result.failure = "restored from the snapshot of tick " + std::to_string(from) + ", " + d->message;
                return result;
            }
        }
        const std::vector<uint8_t> again = fresh.snapshot(level_hash);
        if (again != next) {
            result.failure = "restored from the snapshot of tick " + std::to_string(from) + " and stepped to tick " +
                             std::to_string(to) + ", the world's state differs from the original's in " +
                             first_difference(world, next, again) + " (its hash does not show it)";
            return result;
        }
        taken = next;
    }
    return result;
}

}  // namespace game
