// The stepping order of the world's subsystems. An effect with a sim part adds its
// subsystem here, where its inputs (the player, vehicles, objects) are already stepped.
#include "sim/fluid/FluidTank.h"
#include "sim/dust/DustField.h"
#include "sim/objectives/Objectives.h"
#include "sim/objects/ThrownObjects.h"
#include "sim/player/CameraRig.h"
#include "sim/player/Player.h"
#include "sim/rain/RainSim.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/water/WaterSim.h"
#include "sim/weather/Weather.h"
#include "sim/weapon/Weapon.h"
#include "sim/world/World.h"

namespace sim {

void add_standard_subsystems(World& world) {
    const LevelDesc& level = world.level();
    world.add(std::make_unique<Player>(level.rain_intensity));
    // Right after the player: the rain, the water and the renderer read this tick's weather.
    world.add(std::make_unique<Weather>(level.rain_intensity));
    world.add(std::make_unique<Car>(level.car_spawn));
    world.add(std::make_unique<Boat>(level.boat_spawn));
    world.add(std::make_unique<Weapon>(level.seed));
    world.add(std::make_unique<ThrownObjects>());
    // After the weapon and the objects: their shots and flights this tick clear dust.
    if (level.dust.enabled) world.add(std::make_unique<DustField>(level.dust));
    if (level.water.enabled) {
        // After the objects (it reacts to their water entries this tick); boats and
        // floats ride it from the next tick on.
        WaterParams params;
        params.grid.origin_xz = level.water.origin_xz;
        params.grid.size = level.water.size;
        params.grid.spacing_m = level.water.spacing_m;
        params.grid.wave_speed_mps = level.water.wave_speed_mps;
        params.grid.damping_per_s = level.water.damping_per_s;
        auto water = std::make_unique<WaterSim>(params, level, level.seed);
        world.set_sea(water.get());
        world.add(std::move(water));
    }
    if (!level.rain.glass_lower.empty()) {
        // After the car: drops feel this tick's speed and acceleration.
        RainParams params;
        params.cell_size_m = level.rain.cell_size_m;
        world.add(std::make_unique<RainSim>(params, level.rain.glass_lower, level.rain.glass_upper, level.seed));
    }
    if (level.fluid.enabled)  // after the objects and the boat: it reads where they are this tick
        world.add(std::make_unique<FluidTank>(level.fluid, level.tank_spot, level.seed));
    if (!level.objectives.empty()) {
        // After the vehicles, objects and shots: it judges where they are this tick and
        // changes nothing any other subsystem reads.
        world.add(std::make_unique<Objectives>(level.objectives, glm::vec2(level.car_spawn.position.x, level.car_spawn.position.z),
                                               glm::vec2(level.boat_spawn.position.x, level.boat_spawn.position.z)));
    }
    world.add(std::make_unique<CameraRig>());
}

}  // namespace sim
