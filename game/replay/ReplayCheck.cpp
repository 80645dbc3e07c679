#include "game/replay/ReplayCheck.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>

namespace game {

namespace {
std::string hex(uint64_t v) {
    char buf[24];
    std::snprintf(buf, sizeof buf, "%016" PRIx64, v);
    return buf;
}
}  // namespace

std::optional<std::string> replay_mismatch(const Replay& replay, const sim::World& world, uint64_t level_hash) {
    const ReplayHeader& h = replay.header;
    if (h.level_hash != level_hash)
        return "it was recorded on level '" + h.level_id + "' with content hash " + hex(h.level_hash) +
               ", but that level's files now hash to " + hex(level_hash) + " (re-record it from its .script)";
    if (h.sim_signature != world.sim_signature())
        return "it was recorded by a different simulation (simulation signature " + hex(h.sim_signature) +
               ", this one is " + hex(world.sim_signature()) + "): re-record it from its .script";
    if (h.subsystem_names != world.subsystem_names())
        return "its subsystem list does not match this simulation's";
    if (h.tick_rate_hz != uint32_t(sim::kTickRateHz))
        return "it runs at " + std::to_string(h.tick_rate_hz) + " Hz, the simulation at " +
               std::to_string(sim::kTickRateHz) + " Hz";
    return std::nullopt;
}

std::optional<Divergence> ReplayChecker::after_step(const sim::World& world) {
    const uint64_t tick = world.tick();
    if (world.restore_generation() != restore_generation_) {
        restore_generation_ = world.restore_generation();
        next_chunk_ = 0;  // the world may have gone back
    }
    const auto& world_hashes = replay_.tick_world_hashes;
    if (tick == 0 || tick > world_hashes.size()) return std::nullopt;
    ++checked_;
    const sim::WorldHash got = world.hash();
    const std::vector<std::string>& names = replay_.header.subsystem_names;
    const size_t parts = std::min(names.size(), got.parts.size());

    // Subsystems whose recorded fingerprint differs, first to last in step order.
    std::vector<std::string> by_fingerprint;
    const size_t at = size_t(tick - 1) * names.size();
    for (size_t i = 0; i < parts && at + i < replay_.tick_fingerprints.size(); ++i)
        if (replay_.tick_fingerprints[at + i] != part_fingerprint(got.parts[i])) by_fingerprint.push_back(names[i]);
    // The full subsystem hashes, where this tick ends a chunk: exact where fingerprints are not.
    const auto& chunk_ends = replay_.hashes;
    while (next_chunk_ < chunk_ends.size() && chunk_ends[next_chunk_].tick < tick) ++next_chunk_;
    const bool chunk_end = next_chunk_ < chunk_ends.size() && chunk_ends[next_chunk_].tick == tick;
    const sim::WorldHash* full = chunk_end ? &chunk_ends[next_chunk_].hash : nullptr;
    std::vector<std::string> by_full;
    if (full)
        for (size_t i = 0; i < parts && i < full->parts.size(); ++i)
            if (full->parts[i] != got.parts[i]) by_full.push_back(names[i]);

    const uint64_t want = world_hashes[tick - 1];
    const std::string world_hash = "tick " + std::to_string(tick) + ": world hash " + hex(got.world);
    if (got.world != want) {
        const std::string what = world_hash + " differs from the recorded " + hex(want);
        if (full) return divergence(tick, what, by_full, "no subsystem hash differs at this tick");
        return divergence(tick, what, by_fingerprint, "no subsystem fingerprint differs at this tick");
    }
    // The world hash combines the parts, so these need a hash collision or a damaged recording.
    if (full && (!by_full.empty() || full->parts.size() != got.parts.size()))
        return divergence(tick,
                          world_hash + " matches the recording but the subsystem hashes recorded at this chunk's end do not",
                          by_full, "their count differs");
    if (!by_fingerprint.empty())
        return divergence(tick, world_hash + " matches the recording but the recorded subsystem fingerprints do not",
                          by_fingerprint, "");
    return std::nullopt;
}

Divergence ReplayChecker::divergence(uint64_t tick, const std::string& what, const std::vector<std::string>& differing,
                                     const std::string& none_differ) {
    Divergence d{uint32_t(tick), what};
    if (differing.empty()) {
        d.message += "; " + none_differ;
        return d;
    }
    d.message += "; subsystem '" + differing.front() + "' differs first";
    if (differing.size() > 1) {
        d.message += " (then: ";
        for (size_t i = 1; i < differing.size(); ++i) d.message += (i > 1 ? ", " : "") + differing[i];
        d.message += ")";
    }
    return d;
}

}  // namespace game
