#pragma once
// A replay raced in play (spindrift play --ghost REPLAY): the replay's world, a second
// World of the same level, stepped with the replay's inputs tick for tick beside the
// player's (after each live tick, the ghost's tick), so its vehicle is exactly where
// the recording had it at every tick; once the replay ends it waits where it stopped.
// Each course's gate passes are counted in both worlds; the gap at a gate is how many
// ticks later (positive) or earlier the player passed it than the ghost did.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "effects/scene/FramePoses.h"
#include "game/replay/ReplayReader.h"
#include "sim/world/LevelDesc.h"
#include "sim/world/World.h"

namespace game {

// The ticks (World::tick() after the step) at which a world's vehicles passed each
// course's gates, in order: pass n of a course is its gate n % gate count.
class GatePasses {
public:
    void after_tick(const sim::World& world);
    // Per course (the level's order), the tick of each pass.
    const std::vector<std::vector<uint64_t>>& ticks() const { return ticks_; }

private:
    std::vector<std::vector<uint64_t>> ticks_;
    std::vector<size_t> next_gate_;  // each course's next gate after the last tick
};

struct GateGap {
    std::string course;
    size_t gate = 0;         // 0 is the start and finish
    uint32_t lap = 0;        // the lap the pass ends (gate 0) or lies in, from 1; 0: the start
    int64_t gap_ticks = 0;   // the player's pass tick minus the ghost's
};

class GhostRace {
public:
    // `level` is the live session's; the replay must be of it (replay_mismatch). `name`
    // says which replay it is on the HUD.
    GhostRace(Replay replay, std::string name, const sim::LevelDesc& level, int threads);

    // After each tick of the live world: the ghost steps to the same tick and the gates
    // passed are compared.
    void after_live_tick(const sim::World& live);
    // The live course started again (the menu's Restart): so does the ghost.
    void restart();

    // The ghost's vehicle as of its last tick, and `alpha` (0..1) of the way there from
    // the tick before, as play draws the live vehicles between their last two ticks.
    effects::FramePoses::Ghost pose() const;
    effects::FramePoses::Ghost pose_between(float alpha) const;
    const sim::World& world() const { return *world_; }
    const Replay& replay() const { return replay_; }
    const std::string& name() const { return name_; }
    bool finished() const { return world_->tick() >= replay_.inputs.size(); }
    // Every gap so far, in the order the later of the two passes happened.
    const std::vector<GateGap>& gaps() const { return gaps_; }
    // The live tick of the latest gap's deciding pass (for how long the HUD shows it).
    uint64_t latest_gap_tick() const { return latest_gap_tick_; }

private:
    void compare(uint64_t now);

    Replay replay_;
    std::string name_;
    sim::LevelDesc level_;
    int threads_;
    std::unique_ptr<sim::World> world_;
    effects::FramePoses::Ghost previous_;
    GatePasses live_, ghost_;
    std::vector<size_t> compared_;  // per course: the passes whose gap is known
    std::vector<GateGap> gaps_;
    uint64_t latest_gap_tick_ = 0;
};

}  // namespace game
