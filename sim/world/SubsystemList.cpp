// The game's subsystems in their stepping order, each with what it reads of the others.
// An effect with a sim part adds its entry here, after the subsystems whose state of
// this tick it needs. What a subsystem reads stepped later (the player reads where the
// vehicles were at the end of the last tick) it sees as of the last tick.
#include <stdexcept>
#include <string>

#include "sim/dust/DustField.h"
#include "sim/fluid/FluidTank.h"
#include "sim/objectives/Objectives.h"
#include "sim/objects/ThrownObjects.h"
#include "sim/player/CameraRig.h"
#include "sim/player/Player.h"
#include "sim/rain/RainSim.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/water/WaterSim.h"
#include "sim/weapon/Weapon.h"
#include "sim/weather/Weather.h"
#include "sim/world/SubsystemEntry.h"

namespace sim {

std::vector<SubsystemEntry> standard_subsystems() {
    return {
        {"player", {"car", "boat"}, {},
         [](const LevelDesc& level) { return std::make_unique<Player>(level.rain_intensity); }},
        // Right after the player: the rain, the water and the renderer read this tick's weather.
        {"weather", {}, {"player"}, [](const LevelDesc& level) { return std::make_unique<Weather>(level.rain_intensity); }},
        {"car", {"player"}, {}, [](const LevelDesc& level) { return std::make_unique<Car>(level.car_spawn); }},
        {"boat", {"player"}, {}, [](const LevelDesc& level) { return std::make_unique<Boat>(level.boat_spawn); }},
        {"weapon", {"player", "car", "boat"}, {}, [](const LevelDesc& level) { return std::make_unique<Weapon>(level.seed); }},
        {"objects", {"player", "car", "boat"}, {}, [](const LevelDesc&) { return std::make_unique<ThrownObjects>(); }},
        // After the weapon and the objects: their shots and flights this tick clear dust.
        {"dust", {"objects", "weapon"}, {},
         [](const LevelDesc& level) -> std::unique_ptr<Subsystem> {
             if (!level.dust.enabled) return nullptr;
             return std::make_unique<DustField>(level.dust);
         }},
        // After the objects (it reacts to their water entries this tick); boats and
        // floats ride it from the next tick on.
        {"water", {}, {"weather", "boat"},
         [](const LevelDesc& level) -> std::unique_ptr<Subsystem> {
             if (!level.water.enabled) return nullptr;
             WaterParams params;
             params.grid.origin_xz = level.water.origin_xz;
             params.grid.size = level.water.size;
             params.grid.spacing_m = level.water.spacing_m;
             params.grid.wave_speed_mps = level.water.wave_speed_mps;
             params.grid.damping_per_s = level.water.damping_per_s;
             return std::make_unique<WaterSim>(params, level, level.seed);
         }},
        // After the car: drops feel this tick's speed and acceleration.
        {"rain", {}, {"player", "car", "weather"},
         [](const LevelDesc& level) -> std::unique_ptr<Subsystem> {
             if (level.rain.glass_lower.empty()) return nullptr;
             RainParams params;
             params.cell_size_m = level.rain.cell_size_m;
             return std::make_unique<RainSim>(params, level.rain.glass_lower, level.rain.glass_upper, level.seed);
         }},
        // After the objects and the boat: it reads where they are this tick.
        {"fluid", {}, {"boat", "objects"},
         [](const LevelDesc& level) -> std::unique_ptr<Subsystem> {
             if (!level.fluid.enabled) return nullptr;
             return std::make_unique<FluidTank>(level.fluid, level.tank_spot, level.seed);
         }},
        // After the vehicles, objects and shots: it judges where they are this tick and
        // changes nothing any other subsystem reads.
        {"objectives", {"car", "boat", "objects", "weapon"}, {},
         [](const LevelDesc& level) -> std::unique_ptr<Subsystem> {
             if (level.objectives.empty()) return nullptr;
             return std::make_unique<Objectives>(level.objectives,
                                                 glm::vec2(level.car_spawn.position.x, level.car_spawn.position.z),
                                                 glm::vec2(level.boat_spawn.position.x, level.boat_spawn.position.z));
         }},
        {"camera", {"player", "car", "boat"}, {}, [](const LevelDesc&) { return std::make_unique<CameraRig>(); }},
    };
}

std::vector<SubsystemEntry> standard_subsystems(const std::vector<std::string_view>& names) {
    std::vector<SubsystemEntry> all = standard_subsystems(), picked;
    for (std::string_view name : names) entry_named(all, name);  // refuses an unknown name
    for (SubsystemEntry& e : all)
        for (std::string_view name : names)
            if (e.name == name) {
                picked.push_back(std::move(e));
                break;
            }
    return picked;
}

std::vector<SubsystemEntry> standard_subsystems_with_water(const WaterParams& params, std::optional<uint64_t> seed) {
    std::vector<SubsystemEntry> list = standard_subsystems();
    entry_named(list, "water").make = [params, seed](const LevelDesc& level) {
        return std::make_unique<WaterSim>(params, level, seed.value_or(level.seed));
    };
    return list;
}

SubsystemEntry& entry_named(std::vector<SubsystemEntry>& list, std::string_view name) {
    for (SubsystemEntry& e : list)
        if (e.name == name) return e;
    std::string known;
    for (const SubsystemEntry& e : list) known += (known.empty() ? "" : ", ") + std::string(e.name);
    throw std::invalid_argument("no subsystem '" + std::string(name) + "' in the list (it has " + known + ")");
}

}  // namespace sim
