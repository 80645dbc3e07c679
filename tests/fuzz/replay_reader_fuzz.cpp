// The replay reader on any bytes: a Replay that keeps the format's promises, or one
// ReplayError. Both the lenient and the --strict reading, of the bytes as given and of
// the bytes with every CRC recomputed, as a forger would: random mutations almost never
// pass a CRC, and the structural checks behind the CRCs need fuzzing too.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "game/replay/Crc32.h"
#include "game/replay/ReplayReader.h"
#include "tests/fuzz/FuzzCheck.h"

namespace {

using namespace game;
using namespace game::replay_bytes;

void set_u32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + size_t(i)] = uint8_t(v >> (8 * i));
}
void seal(std::vector<uint8_t>& b, size_t from, size_t size) {
    set_u32(b, from + size, crc32(std::span<const uint8_t>(b.data() + from, size)));
}
bool tag_at(const std::vector<uint8_t>& b, size_t at, const std::array<uint8_t, 4>& tag) {
    return b.size() - at >= 4 && std::equal(tag.begin(), tag.end(), b.begin() + std::ptrdiff_t(at));
}

// Recomputes the header's CRC and those of every record it can walk to.
void reseal(std::vector<uint8_t>& b) {
    if (b.size() < kHeaderPrefixBytes) return;
    const size_t header = get_u32(&b[12]);
    if (header < kCrcBytes + kHeaderPrefixBytes || header > b.size()) return;
    seal(b, 0, header - kCrcBytes);
    for (size_t pos = header; pos < b.size();) {
        const size_t left = b.size() - pos;
        if (tag_at(b, pos, kChunkTag) && left >= kChunkHeaderBytes) {
            seal(b, pos, 16);
            const uint64_t count = get_u32(&b[pos + 8]), parts = get_u32(&b[pos + 12]);
            if (count > kMaxChunkTicks || parts > kMaxSubsystems) return;
            const size_t payload = chunk_payload_bytes(count, parts);
            if (left < kChunkHeaderBytes + payload + kCrcBytes) return;
            seal(b, pos + kChunkHeaderBytes, payload);
            pos += kChunkHeaderBytes + payload + kCrcBytes;
        } else if (tag_at(b, pos, kEndTag) && left >= kEndRecordBytes) {
            seal(b, pos, 12);
            return;
        } else {
            return;
        }
    }
}

void check_reading(std::span<const uint8_t> bytes) {
    for (const bool strict : {false, true}) {
        try {
            const Replay r = parse_replay(bytes, "fuzz.replay", ReadOptions{strict});
            const size_t parts = r.header.subsystem_names.size();
            FUZZ_CHECK(replay_header_problem(r.header).empty());
            FUZZ_CHECK(r.inputs.size() <= kMaxReplayTicks);
            FUZZ_CHECK(r.tick_world_hashes.size() == r.inputs.size());
            FUZZ_CHECK(r.tick_fingerprints.size() == r.inputs.size() * parts);
            FUZZ_CHECK(!strict || r.complete);
            FUZZ_CHECK(r.complete == r.cut_note.empty());
            uint32_t previous = 0;
            for (const ReplayCheckpointHash& h : r.hashes) {
                FUZZ_CHECK(h.tick > previous && h.tick <= r.inputs.size());
                FUZZ_CHECK(h.hash.parts.size() == parts);
                FUZZ_CHECK(h.hash.world == r.tick_world_hashes[h.tick - 1]);
                previous = h.tick;
            }
            FUZZ_CHECK(r.hashes.empty() ? r.inputs.empty() : r.hashes.back().tick == r.inputs.size());
        } catch (const ReplayError&) {
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    check_reading(std::span<const uint8_t>(data, size));
    std::vector<uint8_t> resealed(data, data + size);
    reseal(resealed);
    check_reading(resealed);
    return 0;
}
