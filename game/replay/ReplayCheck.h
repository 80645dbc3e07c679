#pragma once
// Replays a recording into a world, comparing the hashes it stored with the ones the
// world computes now, at every tick. The first difference names the tick and the subsystem.
#include <optional>
#include <string>
#include <vector>

#include "game/replay/ReplayReader.h"
#include "sim/world/World.h"

namespace game {

struct Divergence {
    uint32_t tick = 0;
    // "tick 437: world hash X differs from the recorded Y; subsystem 'car' differs first (then: camera)"
    std::string message;
};

// Checks that the replay fits this world (level content, simulation signature, subsystems,
// tick rate); returns what does not, or nothing.
std::optional<std::string> replay_mismatch(const Replay& replay, const sim::World& world, uint64_t level_hash);

class ReplayChecker {
public:
    explicit ReplayChecker(const Replay& replay) : replay_(replay) {}
    // Call after each world.step(): compares the world hash stored for world.tick() and, at a
    // chunk's last tick, the full subsystem hashes. Ticks the replay holds nothing for (0, or
    // past its end) are not checked. A world restored from a snapshot since the last call
    // (World::restore_generation) is followed from its new tick on.
    std::optional<Divergence> after_step(const sim::World& world);
    size_t hashes_checked() const { return checked_; }  // ticks checked so far

private:
    // `what` followed by the differing subsystems, first to last in step order, or by `none_differ`.
    static Divergence divergence(uint64_t tick, const std::string& what, const std::vector<std::string>& differing,
                                 const std::string& none_differ);

    const Replay& replay_;
    size_t next_chunk_ = 0;  // first entry of replay_.hashes not yet passed
    uint64_t restore_generation_ = 0;
    size_t checked_ = 0;
};

}  // namespace game
