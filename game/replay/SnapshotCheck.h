#pragma once
// The snapshot test (in the manner of 0 A.D.'s serialization test): a replay runs, a
// snapshot is taken every `every` ticks, and each is restored into a fresh world of the
// level and stepped to the next one, where every tick's hash must match the recording
// and the fresh world's snapshot must equal the original's byte for byte (which catches
// state the hashes leave out). `spindrift-check --snapshots N` runs it.
#include <cstdint>
#include <optional>
#include <string>

#include "game/replay/ReplayReader.h"
#include "sim/world/LevelDesc.h"

namespace game {

struct SnapshotCheckResult {
    size_t snapshots = 0;        // restored into fresh worlds
    size_t ticks_restepped = 0;  // by the fresh worlds, each hash checked
    size_t largest_bytes = 0;    // the largest snapshot
    std::optional<std::string> failure;  // the first thing that did not match
};

// `level` and `level_hash` as the session loaded them (the replay's seed already set).
SnapshotCheckResult check_snapshots(const Replay& replay, const sim::LevelDesc& level, uint64_t level_hash,
                                    uint32_t every, int threads);

}  // namespace game
