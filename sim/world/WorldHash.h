#pragma once
#include <cstdint>
#include <vector>

namespace sim {

// The world hash after a tick: one 64-bit hash per subsystem, in World's fixed
// subsystem order (see World::subsystem_names()), and their ordered combination.
struct WorldHash {
    uint64_t world = 0;
    std::vector<uint64_t> parts;
    bool operator==(const WorldHash&) const = default;
};

}  // namespace sim
