// The replay reader on any bytes: a Replay that keeps the format's promises, or one
// ReplayError. Both the lenient and the --strict reading.
#include <cstddef>
#include <cstdint>
#include <span>

#include "game/replay/ReplayReader.h"
#include "tests/fuzz/FuzzCheck.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::span<const uint8_t> bytes(data, size);
    for (const bool strict : {false, true}) {
        try {
            const game::Replay r = game::parse_replay(bytes, "fuzz.replay", game::ReadOptions{strict});
            const size_t parts = r.header.subsystem_names.size();
            FUZZ_CHECK(game::replay_header_problem(r.header).empty());
            FUZZ_CHECK(r.inputs.size() <= game::kMaxReplayTicks);
            FUZZ_CHECK(r.tick_world_hashes.size() == r.inputs.size());
            FUZZ_CHECK(r.tick_fingerprints.size() == r.inputs.size() * parts);
            FUZZ_CHECK(!strict || r.complete);
            FUZZ_CHECK(r.complete == r.cut_note.empty());
            uint32_t previous = 0;
            for (const game::ReplayCheckpointHash& h : r.hashes) {
                FUZZ_CHECK(h.tick > previous && h.tick <= r.inputs.size());
                FUZZ_CHECK(h.hash.parts.size() == parts);
                FUZZ_CHECK(h.hash.world == r.tick_world_hashes[h.tick - 1]);
                previous = h.tick;
            }
            FUZZ_CHECK(r.hashes.empty() ? r.inputs.empty() : r.hashes.back().tick == r.inputs.size());
        } catch (const game::ReplayError&) {
        }
    }
    return 0;
}
