#pragma once
// A subsystem as the world is assembled from it: its name, which others it reads, and
// how it is made for a level. The game's list is sim/world/SubsystemList.cpp.
#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "sim/world/LevelDesc.h"
#include "sim/world/Subsystem.h"

namespace sim {

struct WaterParams;

struct SubsystemEntry {
    std::string_view name;
    std::vector<std::string_view> reads;     // assembly fails when the world lacks one
    std::vector<std::string_view> may_read;  // read when the world has it
    // nullptr where the level has none (no wave grid, no rain glass, ...).
    std::function<std::unique_ptr<Subsystem>(const LevelDesc&)> make;
};

// The game's subsystems in their stepping order.
std::vector<SubsystemEntry> standard_subsystems();
// Just the named ones of the game's list, in its order (a bench or a test that needs
// only a few); std::invalid_argument for a name the list does not have.
std::vector<SubsystemEntry> standard_subsystems(const std::vector<std::string_view>& names);
// The game's list with the water made from `params` (and `seed`, else the level's)
// whatever the level says: a bench or a test that needs a wave grid of its own.
std::vector<SubsystemEntry> standard_subsystems_with_water(const WaterParams& params, std::optional<uint64_t> seed = {});
// The entry called `name`; std::invalid_argument when the list has none.
SubsystemEntry& entry_named(std::vector<SubsystemEntry>& list, std::string_view name);

}  // namespace sim
