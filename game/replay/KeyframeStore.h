#pragma once
// Keyframes of a replay being watched (docs/REPLAYS.md, "Seeking"): world snapshots
// (World::snapshot) kept every `interval` ticks as the replay is stepped, compressed
// with zstd, so that a seek restores the nearest one at or before its target and
// re-simulates the rest without rendering (ReplaySeeker). No GL: tests and the bench use
// it as the viewer does.
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "sim/world/World.h"

namespace game {

class KeyframeStore {
public:
    // A keyframe every `interval_ticks` (300: five seconds), at zstd `level` (1: fast).
    explicit KeyframeStore(uint64_t level_hash, uint32_t interval_ticks = 300, int level = 1);

    // Keeps a keyframe of `world` when its tick is on the interval and none is kept yet.
    void offer(const sim::World& world);
    // The tick of the latest keyframe at or before `tick`, if any.
    std::optional<uint64_t> at_or_before(uint64_t tick) const;
    // Restores the keyframe of `tick` (one at_or_before returned) into `world`.
    void restore(uint64_t tick, sim::World& world) const;

    uint32_t interval() const { return interval_; }
    uint64_t level_hash() const { return level_hash_; }
    size_t count() const { return frames_.size(); }
    size_t compressed_bytes() const { return compressed_; }
    size_t raw_bytes() const { return raw_; }  // what they would take uncompressed

private:
    uint64_t level_hash_;
    uint32_t interval_;
    int level_;
    std::map<uint64_t, std::vector<uint8_t>> frames_;  // by tick, zstd frames
    size_t compressed_ = 0, raw_ = 0;
    mutable std::vector<uint8_t> scratch_;  // a decompressed snapshot
};

}  // namespace game
