#include "game/replay/TakeOverRecording.h"

#include <algorithm>
#include <string>

namespace game {

namespace {

// The old header without what belonged to the old drive from `tick` on; checked before
// any file is made.
ReplayHeader header_until(const Replay& old, uint64_t tick) {
    if (tick > old.inputs.size())
        throw ReplayError("take over at tick " + std::to_string(tick) + ", past the replay's end (" +
                          std::to_string(old.inputs.size()) + " ticks)");
    ReplayHeader h = old.header;
    std::erase_if(h.checkpoints, [&](uint32_t t) { return t >= tick; });
    std::erase_if(h.camera_shots, [&](const CameraShot& s) { return s.tick >= tick; });
    return h;
}

}  // namespace

TakeOverRecording::TakeOverRecording(const std::filesystem::path& out, const Replay& old, uint64_t tick,
                                     const sim::LevelDesc& level, int threads)
    : writer_(ReplayWriter::create(out, header_until(old, tick))) {
    sim::World world(level, sim::WorldOptions{threads});
    for (size_t t = 0; t < tick; ++t) {
        world.step(old.inputs[t]);
        const sim::WorldHash h = world.hash();
        if (h.world != old.tick_world_hashes[t]) {
            writer_.discard();
            throw ReplayError("the replay desyncs at tick " + std::to_string(t + 1) + " before the take over");
        }
        writer_.append(old.inputs[t], h);
    }
}

}  // namespace game
