#pragma once
// Taking over a replay at a tick (docs/REPLAYS.md, "Take over"): the new recording holds
// the old replay's inputs up to that tick and then whatever is played from it, so it
// checks from tick 0 like any other. The old inputs' hashes are recorded by stepping
// them again in a world of their own (the replay stores no full subsystem hashes per
// tick); they are checked against the old recording on the way. No GL.
#include <cstdint>
#include <filesystem>

#include "game/replay/ReplayReader.h"
#include "game/replay/ReplayWriter.h"
#include "sim/world/LevelDesc.h"
#include "sim/world/World.h"

namespace game {

class TakeOverRecording {
public:
    // `level` is the replay's (its seed set), `tick` where the player takes over (at most
    // the replay's length). Keeps the old header but for checkpoints and camera lines
    // from `tick` on, which belonged to the old drive. Throws ReplayError if the old
    // inputs no longer give their recorded hashes.
    TakeOverRecording(const std::filesystem::path& out, const Replay& old, uint64_t tick, const sim::LevelDesc& level,
                      int threads = 1);

    // After each tick played from the take over, with the input applied.
    void append(sim::TickInput applied, const sim::World& world) { writer_.append(applied, world.hash()); }
    void finish() { writer_.finish(); }
    uint32_t ticks() const { return writer_.ticks(); }
    const std::filesystem::path& path() const { return writer_.path(); }

private:
    ReplayWriter writer_;
};

}  // namespace game
