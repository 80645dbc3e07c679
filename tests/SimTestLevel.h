#pragma once
// A small level built in code, so sim tests need no files: land for z < 0, sea
// beyond, a road, a deck (pier) and one solid box.
#include "sim/world/LevelDesc.h"

inline sim::LevelDesc make_test_level() {
    sim::LevelDesc l;
    l.id = "test";
    l.seed = 7;
    l.half_extent_m = 200.0f;
    l.land_height_m = 1.0f;
    l.shore_z_m = 0.0f;
    l.sea_level_m = 0.0f;
    l.seabed_m = -6.0f;
    l.roads.push_back({{-200.0f, -20.0f}, {200.0f, -5.0f}});
    l.decks.push_back({{20.0f, 0.6f, -1.0f}, {28.0f, 1.0f, 40.0f}});
    l.solids.push_back({{150.0f, 1.0f, -20.0f}, {154.0f, 4.0f, -5.0f}});  // a wall across the road
    l.car_spawn = {{0.0f, 1.0f, -12.0f}, 0.0f};
    l.boat_spawn = {{40.0f, 0.0f, 30.0f}, -1.5707963f};
    return l;
}
