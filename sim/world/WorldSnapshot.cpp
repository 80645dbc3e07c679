// World::snapshot and World::restore. The layout (little-endian; docs/REPLAYS.md):
//
//   magic "SPDSNAP\x1A"[8] format:u32 sim_signature:u64 level_hash:u64
//   tick:u64 previous_input (held:u16 throttle:u8 brake:u8 steer:i8)
//   subsystem_count:u32, then per subsystem: byte_count:u64 bytes (its description,
//   sim/core/StateArchive.h, in the world's subsystem order)
#include <cstring>
#include <sstream>
#include <string>

#include "sim/core/StateArchive.h"
#include "sim/world/World.h"

namespace sim {

namespace {

constexpr char kMagic[8] = {'S', 'P', 'D', 'S', 'N', 'A', 'P', '\x1A'};
constexpr uint32_t kFormat = 1;

std::string hex(uint64_t v) {
    std::ostringstream s;
    s << std::hex << v;
    return s.str();
}

template <class T> void put(std::vector<uint8_t>& out, const T& v) {
    const size_t at = out.size();
    out.resize(at + sizeof v);
    std::memcpy(out.data() + at, &v, sizeof v);
}

}  // namespace

std::vector<uint8_t> World::snapshot(uint64_t level_hash) const {
    std::vector<uint8_t> out(sizeof kMagic);
    std::memcpy(out.data(), kMagic, sizeof kMagic);
    put(out, kFormat);
    put(out, sim_signature());
    put(out, level_hash);
    put(out, tick_);
    put(out, previous_.held);
    put(out, previous_.throttle);
    put(out, previous_.brake);
    put(out, previous_.steer);
    put(out, uint32_t(subsystems_.size()));
    for (const auto& s : subsystems_) {
        const size_t at = out.size();
        put(out, uint64_t(0));
        StateWriter w(out);
        s->save(w);
        const uint64_t bytes = out.size() - at - sizeof(uint64_t);
        std::memcpy(out.data() + at, &bytes, sizeof bytes);
    }
    return out;
}

void World::restore(std::span<const uint8_t> snapshot, uint64_t level_hash) {
    StateReader in(snapshot);
    char magic[8];
    for (char& c : magic) in.raw(c);
    if (std::memcmp(magic, kMagic, sizeof magic) != 0) throw SnapshotError("not a Spindrift world snapshot (bad magic)");
    uint32_t format = 0;
    in.u32(format);
    if (format != kFormat)
        throw SnapshotError("snapshot format " + std::to_string(format) + " is not this program's (" +
                            std::to_string(kFormat) + ")");
    uint64_t signature = 0, level = 0, tick = 0;
    in.u64(signature);
    in.u64(level);
    in.u64(tick);
    if (signature != sim_signature())
        throw SnapshotError("the snapshot was taken by another simulation (signature " + hex(signature) +
                            ", this world's is " + hex(sim_signature()) +
                            "): another sim version or other subsystems; it cannot be restored here");
    if (level != level_hash)
        throw SnapshotError("the snapshot is of another level (content hash " + hex(level) + ", this world's level '" +
                            level_.id + "' hashes to " + hex(level_hash) + "); it cannot be restored here");
    TickInput previous;
    in.raw(previous.held);
    in.raw(previous.throttle);
    in.raw(previous.brake);
    in.raw(previous.steer);
    uint32_t count = 0;
    in.u32(count);
    if (count != subsystems_.size())  // the signature names them: only a corrupt file gets here
        throw SnapshotError("the snapshot has " + std::to_string(count) + " subsystems, this world " +
                            std::to_string(subsystems_.size()));
    for (const auto& s : subsystems_) {
        uint64_t bytes = 0;
        in.u64(bytes);
        StateReader part(in.bytes(bytes, s->name()));
        s->restore(part);
        if (part.remaining() != 0)
            throw SnapshotError("snapshot: subsystem '" + std::string(s->name()) + "' has " +
                                std::to_string(part.remaining()) + " bytes its description does not read");
    }
    if (in.remaining() != 0) throw SnapshotError("snapshot: " + std::to_string(in.remaining()) + " trailing bytes");
    tick_ = tick;
    previous_ = previous;
    events_.clear();
    ++restore_generation_;
}

}  // namespace sim
