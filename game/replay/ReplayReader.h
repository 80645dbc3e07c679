#pragma once
// Reads and validates replay files (layout in ReplayFormat.h). Every fault is a ReplayError
// naming the file and what is wrong; no input can crash, hang or allocate without bound.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "game/replay/ReplayError.h"
#include "game/replay/ReplayFormat.h"
#include "sim/core/TickInput.h"
#include "sim/world/WorldHash.h"

namespace game {

struct ReplayCheckpointHash {
    uint32_t tick = 0;      // ticks applied when the hash was taken (world.tick() after)
    sim::WorldHash hash;
    bool operator==(const ReplayCheckpointHash&) const = default;
};

struct Replay {
    ReplayHeader header;
    std::vector<sim::TickInput> inputs;        // one per tick
    std::vector<ReplayCheckpointHash> hashes;  // one per chunk: the full hash after its last tick
    // Per tick i (0-based, as inputs): the world hash after i + 1 ticks, and from index
    // i * part_count the fingerprints (part_fingerprint) of the subsystem hashes after
    // i + 1 ticks, part_count = header.subsystem_names.size().
    std::vector<uint64_t> tick_world_hashes;   // size == inputs.size()
    std::vector<uint8_t> tick_fingerprints;    // size == inputs.size() * part_count
    bool complete = true;   // false if the recording was cut (no END record or a partial last record)
    // When !complete: where it was cut and what remains, without the file name, e.g. "recording was cut
    // after tick 1260 (byte 12345 of 13000, inside chunk 21 (ticks 1260..1319)): replaying the 1260
    // ticks of its 21 complete chunks".
    std::string cut_note;
};

struct ReadOptions {
    bool strict = false;  // refuse cut recordings instead of replaying their whole chunks
};

Replay read_replay(const std::filesystem::path& path, const ReadOptions& options = {});
// The same from memory; `name` stands for the file in messages.
Replay parse_replay(std::span<const uint8_t> bytes, std::string_view name, const ReadOptions& options = {});

}  // namespace game
