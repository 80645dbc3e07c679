// The stepping order of the world's subsystems. An effect with a sim part adds its
// subsystem here, where its inputs (the player, vehicles, objects) are already stepped.
#include "sim/objects/ThrownObjects.h"
#include "sim/player/CameraRig.h"
#include "sim/player/Player.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/weapon/Weapon.h"
#include "sim/world/World.h"

namespace sim {

void add_standard_subsystems(World& world) {
    const LevelDesc& level = world.level();
    world.add(std::make_unique<Player>(level.rain_intensity));
    world.add(std::make_unique<Car>(level.car_spawn));
    world.add(std::make_unique<Boat>(level.boat_spawn));
    world.add(std::make_unique<Weapon>(level.seed));
    world.add(std::make_unique<ThrownObjects>());
    world.add(std::make_unique<CameraRig>());
}

}  // namespace sim
