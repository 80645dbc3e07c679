// Backspace: the driven vehicle back upright and stopped, the car on the nearest road
// along it, the boat on open water; an ordinary one-shot input that replays carry.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "SimInput.h"
#include "SimTestLevel.h"
#include "game/replay/InputScript.h"
#include "game/replay/ReplayReader.h"
#include "game/replay/ReplayWriter.h"
#include "sim/player/Player.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/world/World.h"

namespace {

using sim::Control;
using sim::TickInput;

constexpr float kPi = 3.14159265f;

void tap(sim::World& w, Control c) {
    w.step(held({c}));
    w.step({});
}

// Both axle circles clear of solids and every body corner over land.
bool car_fits(const sim::World& w) {
    const sim::Car& car = w.get<sim::Car>();
    const sim::Terrain& terrain = w.terrain();
    const sim::CarParams& p = car.params();
    glm::vec3 f = car.pose().forward_flat(), r = car.pose().right_flat(), c = car.position();
    for (float along : {p.cg_to_front_m, -p.cg_to_rear_m}) {
        glm::vec2 axle(c.x + f.x * along, c.z + f.z * along);
        if (terrain.resolve_solids(axle, p.radius_m - 0.01f, c.y + 0.25f, c.y + p.height_m)) return false;
    }
    for (float along : {p.cg_to_front_m + 0.8f, -p.cg_to_rear_m - 0.8f})
        for (float side : {-0.9f, 0.9f}) {
            glm::vec2 corner(c.x + f.x * along + r.x * side, c.z + f.z * along + r.z * side);
            if (terrain.support_height(corner, c.y) < terrain.level().sea_level_m + 0.1f) return false;
        }
    return true;
}

// Upright, stopped, in the middle of the test level's road (z -20..-5), along it.
void expect_reset_onto_the_road(const sim::World& w) {
    const sim::Car& car = w.get<sim::Car>();
    EXPECT_NEAR(car.position().z, -12.5f, 1e-4f);
    EXPECT_TRUE(w.terrain().on_road({car.position().x, car.position().z}));
    EXPECT_EQ(car.speed_mps(), 0.0f);
    EXPECT_EQ(car.pose().pitch_rad, 0.0f);
    EXPECT_EQ(car.pose().roll_rad, 0.0f);
    float s = std::sin(car.pose().heading_rad);
    EXPECT_NEAR(s, 0.0f, 1e-4f);  // along the road, which runs in x
    EXPECT_TRUE(car_fits(w));
}

TEST(VehicleReset, PutsACarPinnedAtTheQuayBackOnTheRoad) {
    sim::LevelDesc l = make_test_level();
    l.car_spawn = {{0.0f, 1.0f, -8.0f}, -kPi / 2.0f};  // facing the sea
    sim::World w(l);
    run(w, 240, held({Control::Throttle}));
    ASSERT_GT(w.get<sim::Car>().position().z, -4.0f);  // off the road, nosed into the water's edge
    tap(w, Control::Reset);
    expect_reset_onto_the_road(w);
    // Facing +x or -x, whichever is nearer to where it faced: then it drives off freely.
    float x0 = w.get<sim::Car>().position().x;
    run(w, 60, held({Control::Throttle}));
    EXPECT_GT(std::fabs(w.get<sim::Car>().position().x - x0), 2.0f);
}

TEST(VehicleReset, FindsAFreeStretchOfRoadBesideAWall) {
    // Driven into the wall across the road and turned into its corner with the road's
    // edge: the reset spot is on the road but clear of the wall.
    sim::LevelDesc l = make_test_level();
    l.car_spawn = {{140.0f, 1.0f, -12.5f}, 0.0f};
    sim::World w(l);
    run(w, 240, held({Control::Throttle, Control::SteerLeft}));
    tap(w, Control::Reset);
    expect_reset_onto_the_road(w);
    EXPECT_LT(w.get<sim::Car>().position().x, 150.0f - 2.3f);
}

TEST(VehicleReset, ActsOnlyOnTheDrivenVehicle) {
    sim::World w(make_test_level());
    run(w, 120, held({Control::Throttle}));
    sim::Pose boat = w.get<sim::Boat>().pose();
    tap(w, Control::Reset);
    EXPECT_EQ(w.get<sim::Boat>().position().x, boat.position.x);
    EXPECT_EQ(w.get<sim::Boat>().position().z, boat.position.z);
}

// The test level with the car by the pier and the boat aground near the shore.
sim::LevelDesc boat_aground_level() {
    sim::LevelDesc l = make_test_level();
    l.car_spawn = {{40.0f, 1.0f, -8.0f}, 0.0f};
    l.boat_spawn = {{40.0f, 0.0f, 0.6f}, 0.3f};  // in a hand's depth of water
    return l;
}

TEST(VehicleReset, PutsABoatAgroundBackOnOpenWater) {
    sim::World w(boat_aground_level());
    tap(w, Control::SwitchVehicle);
    ASSERT_EQ(w.get<sim::Player>().vehicle(), sim::Vehicle::Boat);
    tap(w, Control::Reset);
    const sim::Boat& boat = w.get<sim::Boat>();
    const sim::Terrain& terrain = w.terrain();
    glm::vec3 p = boat.position();
    EXPECT_LT(terrain.ground_height({p.x, p.z}), -boat.params().min_depth_m);
    // The whole hull is over deep water.
    glm::vec3 f = boat.pose().forward_flat();
    for (float along : {-0.5f, 0.5f}) {
        glm::vec3 end = p + f * (along * boat.params().length_m);
        EXPECT_LT(terrain.ground_height({end.x, end.z}), -boat.params().min_depth_m);
    }
    EXPECT_LT(std::fabs(boat.speed_mps()), 0.05f);
    EXPECT_LT(std::fabs(boat.pose().pitch_rad), 0.02f);
    EXPECT_LT(std::fabs(boat.pose().roll_rad), 0.02f);
    EXPECT_LT(p.z, 8.0f);  // the nearest open water, not anywhere
    float z0 = p.z;
    run(w, 120, held({Control::Throttle}));  // heading 0.3: out along the shore
    EXPECT_GT(std::fabs(boat.position().x - p.x) + std::fabs(boat.position().z - z0), 3.0f);
}

// A script with a reset, recorded to a replay file and read back, replays to the same
// world: the reset is an input like any other.
TEST(VehicleReset, RoundTripsThroughAReplay) {
    const game::InputScript script = game::parse_script(
        "0 hold throttle steer_left\n200 hold throttle\n240 tap reset\n250 hold throttle\n300 end", "reset.script");
    ASSERT_EQ(script.inputs.size(), 300u);
    EXPECT_TRUE(script.inputs[240].has(Control::Reset));
    EXPECT_FALSE(script.inputs[241].has(Control::Reset));

    sim::LevelDesc l = make_test_level();
    l.car_spawn = {{0.0f, 1.0f, -8.0f}, -kPi / 2.0f};
    sim::World recorded(l);
    namespace fs = std::filesystem;
    fs::path file = fs::temp_directory_path() / ("spindrift_reset_" + std::to_string(::getpid()) + ".replay");
    game::ReplayHeader header;
    header.level_id = "test";
    header.sim_signature = recorded.sim_signature();
    header.subsystem_names = recorded.subsystem_names();
    {
        auto writer = game::ReplayWriter::create(file, header);
        for (const TickInput& in : script.inputs) {
            recorded.step(in);
            writer.append(in, recorded.hash());
        }
        writer.finish();
    }
    const game::Replay replay = game::read_replay(file);
    fs::remove(file);
    ASSERT_EQ(replay.inputs.size(), script.inputs.size());
    sim::World replayed(l);
    for (size_t t = 0; t < replay.inputs.size(); ++t) {
        ASSERT_EQ(replay.inputs[t], script.inputs[t]) << t;
        replayed.step(replay.inputs[t]);
        ASSERT_EQ(replayed.hash().world, replay.tick_world_hashes[t]) << t;
    }
    // The reset happened: the car is on the road's middle line, driving along it.
    EXPECT_NEAR(replayed.get<sim::Car>().position().z, -12.5f, 0.5f);
}

TEST(VehicleReset, IsNamedResetInScripts) {
    EXPECT_EQ(sim::control_from_name("reset"), Control::Reset);
    EXPECT_NE(sim::kOneShotControls & uint16_t(Control::Reset), 0);
}

}  // namespace
