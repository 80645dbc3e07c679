#pragma once
// Brings a world to any tick of a replay (docs/REPLAYS.md, "Seeking"): it steps on from
// where the world is, or restores the latest snapshot at or before the tick and
// re-simulates the rest without rendering. Two kinds of snapshot serve it: the
// keyframes (KeyframeStore: every five seconds, compressed, kept for the whole replay)
// and, within the five seconds the world is in, a raw snapshot every `near_interval`
// ticks, so that stepping back a tick re-simulates at most that many. Both are taken as
// the world passes their ticks, whether it plays or re-simulates. No GL.
#include <cstdint>
#include <map>
#include <vector>

#include "game/replay/KeyframeStore.h"
#include "sim/core/TickInput.h"
#include "sim/world/World.h"

namespace game {

class ReplaySeeker {
public:
    // `world` is the replay's, at tick 0; `inputs` the replay's (one per tick).
    ReplaySeeker(const std::vector<sim::TickInput>& inputs, sim::World& world, KeyframeStore& keyframes,
                 uint32_t near_interval = 30);

    uint64_t ticks() const { return inputs_.size(); }  // the last tick a seek can reach
    uint64_t tick() const { return world_.tick(); }
    // One tick on; false (and nothing done) at the end.
    bool step();
    // To `tick` (at most ticks()). Returns how many ticks it simulated.
    uint64_t seek(uint64_t tick);
    // The world was stepped one tick of the replay elsewhere (the viewer plays through
    // its TickDriver): keeps the snapshots of the tick it reached.
    void after_step();

    size_t near_bytes() const;  // the raw snapshots of the current five seconds

private:
    void advance();  // one tick, keeping snapshots on their ticks

    const std::vector<sim::TickInput>& inputs_;
    sim::World& world_;
    KeyframeStore& keyframes_;
    uint32_t near_interval_;
    std::map<uint64_t, std::vector<uint8_t>> near_;  // within one keyframe interval
};

}  // namespace game
