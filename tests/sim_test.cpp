#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "SimInput.h"
#include "SimTestLevel.h"
#include "sim/core/Hash.h"
#include "sim/core/Rng.h"
#include "sim/objects/ThrownObjects.h"
#include "sim/player/CameraRig.h"
#include "sim/player/Player.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/weapon/Weapon.h"
#include "sim/world/World.h"

namespace {

using sim::Control;
using sim::TickInput;

// Presses a control for one tick, then releases it for one tick.
void tap(sim::World& w, Control c, TickInput base = {}) {
    TickInput in = base;
    in.set(c, true);
    w.step(in);
    w.step(base);
}

TEST(Rng, MatchesPcg32ReferenceSequence) {
    // pcg32_srandom(42, 54) from the PCG reference implementation.
    sim::Rng rng(42u, 54u);
    const uint32_t expected[] = {0xa15c02b7, 0x7b47f409, 0xba1d3330, 0x83d2f293, 0xbfa4784b, 0xcbed606e};
    for (uint32_t e : expected) EXPECT_EQ(rng.next_u32(), e);
}

TEST(Rng, RangesStayInBounds) {
    sim::Rng rng(1);
    for (int i = 0; i < 10000; ++i) {
        float u = rng.unit();
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
        ASSERT_LT(rng.below(7), 7u);
        float r = rng.range(-2.0f, 3.0f);
        ASSERT_GE(r, -2.0f);
        ASSERT_LT(r, 3.0f);
    }
}

TEST(Hash, SeesEveryBitOfAFloat) {
    sim::Hasher a, b;
    a.f32(1.0f);
    b.f32(std::nextafter(1.0f, 2.0f));
    EXPECT_NE(a.value(), b.value());
    sim::Hasher c, d;
    c.f32(0.0f);
    d.f32(-0.0f);
    EXPECT_NE(c.value(), d.value());
}

TEST(World, NamesItsSubsystemsInStepOrder) {
    sim::World w(make_test_level());
    std::vector<std::string> expected = {"player", "weather", "car", "boat", "weapon", "objects", "camera"};
    EXPECT_EQ(w.subsystem_names(), expected);
    EXPECT_EQ(w.hash().parts.size(), expected.size());
}

TEST(Car, AcceleratesForwardAndStopsWithoutReversing) {
    sim::World w(make_test_level());
    run(w, 300, held({Control::Throttle}));
    const sim::Car& car = w.get<sim::Car>();
    EXPECT_GT(car.speed_mps(), 12.0f);
    EXPECT_GT(car.position().x, 25.0f);                // heading 0 drives towards +x
    EXPECT_NEAR(car.position().z, -12.0f, 0.5f);       // straight
    EXPECT_NEAR(car.position().y, 1.0f, 1e-4f);        // on the ground
    int ticks = 0;
    while (car.speed_mps() > 0.0f && ticks < 600) {
        w.step(held({Control::Brake}));
        ++ticks;
    }
    EXPECT_LT(ticks, 240);  // about 1 g of braking from ~70 km/h
    EXPECT_GT(car.speed_mps(), -0.1f);  // braking to a stop, not into reverse
    float x_stopped = car.position().x;
    run(w, 60, TickInput{});
    EXPECT_NEAR(car.position().x, x_stopped, 0.05f);  // and it doesn't creep
    run(w, 300, held({Control::Brake}));  // holding brake at rest reverses, slowly
    EXPECT_LT(car.speed_mps(), -3.0f);
    EXPECT_GT(car.speed_mps(), -5.2f);
}

TEST(Car, SteersLeftAndRight) {
    sim::World left(make_test_level()), right(make_test_level());
    run(left, 200, held({Control::Throttle, Control::SteerLeft}));
    run(right, 200, held({Control::Throttle, Control::SteerRight}));
    EXPECT_GT(left.get<sim::Car>().pose().heading_rad, 0.5f);
    EXPECT_LT(right.get<sim::Car>().pose().heading_rad, -0.5f);
    // Heading positive turns towards -z.
    EXPECT_LT(left.get<sim::Car>().position().z, -12.0f);
}

TEST(Car, ReversesUnderControlAndSteersTheOtherWay) {
    // Reversing with the wheel turned left swings the nose right, like a real car,
    // without spinning out.
    sim::LevelDesc l = make_test_level();
    l.solids.clear();
    sim::World w(l);
    run(w, 180, held({Control::Brake}));
    run(w, 120, held({Control::Brake, Control::SteerLeft}));
    const sim::Car& car = w.get<sim::Car>();
    EXPECT_LT(car.speed_mps(), -3.0f);
    EXPECT_LT(car.pose().heading_rad, -0.3f);
    EXPECT_GT(car.pose().heading_rad, -2.0f);
    // Throttle from reverse slows the car and drives it forward again.
    run(w, 75, held({Control::Throttle}));
    EXPECT_GT(car.speed_mps(), 0.5f);
}

TEST(Car, GripsLessOffRoad) {
    // The same hard turn at speed drifts wider on grass than on the road.
    sim::LevelDesc on = make_test_level();
    sim::LevelDesc off = make_test_level();
    off.roads.clear();
    sim::World a(on), b(off);
    run(a, 240, held({Control::Throttle}));
    run(b, 240, held({Control::Throttle}));
    run(a, 90, held({Control::Throttle, Control::SteerLeft}));
    run(b, 90, held({Control::Throttle, Control::SteerLeft}));
    EXPECT_GT(a.get<sim::Car>().pose().heading_rad, b.get<sim::Car>().pose().heading_rad);
}

TEST(Car, StaysOutOfTheSea) {
    sim::LevelDesc l = make_test_level();
    l.car_spawn = {{0.0f, 1.0f, -10.0f}, -1.5707963f};  // facing +z, the sea
    sim::World w(l);
    run(w, 600, held({Control::Throttle}));
    EXPECT_LT(w.get<sim::Car>().position().z, 0.0f);
    EXPECT_GE(w.get<sim::Car>().position().y, 0.9f);
}

TEST(Car, DrivesOntoTheDeck) {
    sim::LevelDesc l = make_test_level();
    l.car_spawn = {{24.0f, 1.0f, -10.0f}, -1.5707963f};  // facing +z along the pier
    sim::World w(l);
    run(w, 240, held({Control::Throttle}));
    glm::vec3 p = w.get<sim::Car>().position();
    EXPECT_GT(p.z, 5.0f);  // out over the water
    EXPECT_NEAR(p.y, 1.0f, 1e-3f);
}

TEST(Car, StopsAtAWall) {
    sim::World w(make_test_level());
    run(w, 900, held({Control::Throttle}));
    EXPECT_LT(w.get<sim::Car>().position().x, 150.0f);  // the front circle keeps it out of the wall at x = 150
    EXPECT_GT(w.get<sim::Car>().position().x, 140.0f);
}

TEST(Boat, FloatsAtItsWaterlineAtRest) {
    // Set down 0.3 m high, nose up and leaning left: it must settle level at its waterline.
    const sim::LevelDesc level = make_test_level();
    sim::Pose start = sim::Boat(level.boat_spawn).pose();
    start.position.y = 0.3f;
    start.pitch_rad = 0.15f;
    start.roll_rad = -0.2f;
    std::vector<sim::SubsystemEntry> list = sim::standard_subsystems();
    sim::entry_named(list, "boat").make = [start](const sim::LevelDesc&) { return std::make_unique<sim::Boat>(start); };
    sim::World w(level, list);
    const sim::Boat& b = w.get<sim::Boat>();
    float lowest = b.position().y;
    for (int t = 0; t < 600; ++t) {
        w.step({});
        lowest = std::min(lowest, b.position().y);
    }
    EXPECT_LT(lowest, 0.1f);  // it fell onto the water rather than hovering
    EXPECT_NEAR(b.position().y, 0.0f, 0.01f);
    EXPECT_NEAR(b.pose().pitch_rad, 0.0f, 0.01f);
    EXPECT_NEAR(b.pose().roll_rad, 0.0f, 0.01f);
}

TEST(Player, SwitchesToTheBoatOnlyWhenClose) {
    sim::LevelDesc l = make_test_level();
    sim::World far(l);
    tap(far, Control::SwitchVehicle);
    EXPECT_EQ(far.get<sim::Player>().vehicle(), sim::Vehicle::Car);
    l.car_spawn.position = {36.0f, 1.0f, 30.0f};  // pretend the car is at the pier by the boat
    sim::World near(l);
    tap(near, Control::SwitchVehicle);
    EXPECT_EQ(near.get<sim::Player>().vehicle(), sim::Vehicle::Boat);
    run(near, 300, held({Control::Throttle}));
    EXPECT_GT(near.get<sim::Boat>().speed_mps(), 4.0f);
    EXPECT_GT(near.get<sim::Boat>().position().z, 35.0f);  // the boat faces +z
    EXPECT_NEAR(near.get<sim::Car>().position().x, 36.0f, 0.01f);  // the car stays parked
}

TEST(Player, CyclesCameraWipersAndRain) {
    sim::World w(make_test_level());
    tap(w, Control::Camera);
    EXPECT_EQ(w.get<sim::Player>().view(), sim::ViewMode::Driver);
    for (int i = 0; i < 3; ++i) tap(w, Control::Wipers);
    EXPECT_EQ(w.get<sim::Player>().wipers(), sim::WiperMode::High);
    tap(w, Control::Wipers);
    EXPECT_EQ(w.get<sim::Player>().wipers(), sim::WiperMode::Off);
    for (int i = 0; i < 6; ++i) tap(w, Control::RainUp);
    EXPECT_FLOAT_EQ(w.get<sim::Player>().rain_intensity(), 1.0f);
    tap(w, Control::RainDown);
    EXPECT_FLOAT_EQ(w.get<sim::Player>().rain_intensity(), 0.75f);
    // Holding a key acts once.
    sim::World h(make_test_level());
    run(h, 30, held({Control::Camera}));
    EXPECT_EQ(h.get<sim::Player>().view(), sim::ViewMode::Driver);
}

// Where the chase camera's eye is along the car: positive ahead of its nose.
float eye_ahead_of_car(const sim::World& w) {
    const sim::Car& car = w.get<sim::Car>();
    glm::vec3 d = w.get<sim::CameraRig>().view().eye - car.position();
    glm::vec3 f = car.pose().forward_flat();
    return d.x * f.x + d.z * f.z;
}

TEST(CameraRig, TurnsRoundWhileReversingAndBackWhenDrivingOn) {
    sim::LevelDesc l = make_test_level();
    l.solids.clear();
    sim::World w(l);
    run(w, 60, TickInput{});
    EXPECT_LT(eye_ahead_of_car(w), -5.0f);  // behind the car
    // A short reverse, as when backing off a wall, keeps the camera where it is.
    glm::vec3 last_eye = w.get<sim::CameraRig>().view().eye;
    float most_moved = 0.0f;
    auto step = [&](TickInput in) {
        w.step(in);
        glm::vec3 eye = w.get<sim::CameraRig>().view().eye, d = eye - last_eye;
        most_moved = std::max(most_moved, std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z));
        last_eye = eye;
    };
    for (int t = 0; t < 45; ++t) step(held({Control::Brake}));
    ASSERT_LT(w.get<sim::Car>().speed_mps(), -0.5f);
    EXPECT_LT(eye_ahead_of_car(w), -5.0f);
    // Reversing on, it swings round to look the way the car goes...
    for (int t = 0; t < 180; ++t) step(held({Control::Brake}));
    EXPECT_GT(eye_ahead_of_car(w), 5.0f);
    // ... and back behind once the car drives forwards again.
    for (int t = 0; t < 240; ++t) step(held({Control::Throttle}));
    ASSERT_GT(w.get<sim::Car>().speed_mps(), 0.5f);
    EXPECT_LT(eye_ahead_of_car(w), -5.0f);
    // Smoothly: never a jump (the car itself moves at most ~0.25 m a tick here).
    EXPECT_LT(most_moved, 0.6f);
}

TEST(ThrownObjects, SubmergedVolumeOfASphere) {
    const float r = 0.5f, full = 4.0f / 3.0f * 3.14159265f * r * r * r;
    EXPECT_FLOAT_EQ(sim::submerged_sphere_volume(r, -1.0f), 0.0f);
    EXPECT_NEAR(sim::submerged_sphere_volume(r, 0.0f), full / 2, 1e-5f);
    EXPECT_NEAR(sim::submerged_sphere_volume(r, 2.0f), full, 1e-5f);
}

sim::World& world_with_object(sim::World& w, const sim::ThrowKind& kind) {
    // Dropped from above the sea beside the pier.
    w.get<sim::ThrownObjects>().launch(kind, {40.0f, 4.0f, 10.0f}, {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f});
    return w;
}

TEST(ThrownObjects, HeavySinksToTheBottomLightFloats) {
    sim::World heavy(make_test_level()), light(make_test_level());
    world_with_object(heavy, sim::ThrownObjects::kHeavy);
    world_with_object(light, sim::ThrownObjects::kLight);
    int heavy_entries = 0, light_entries = 0;
    for (int i = 0; i < 900; ++i) {
        heavy.step({});
        light.step({});
        heavy_entries += int(heavy.events().water_entries.size());
        light_entries += int(light.events().water_entries.size());
    }
    EXPECT_EQ(heavy_entries, 1);
    EXPECT_EQ(light_entries, 1);
    const sim::ThrownObject& h = heavy.get<sim::ThrownObjects>().objects().at(0);
    const sim::ThrownObject& l = light.get<sim::ThrownObjects>().objects().at(0);
    EXPECT_NEAR(h.position.y, -6.0f + h.radius_m, 0.02f);  // resting on the sea bed
    // A float of density 240 rides with about a quarter of its volume under water:
    // its centre sits above the surface, less than its radius.
    EXPECT_GT(l.position.y, 0.0f);
    EXPECT_LT(l.position.y, l.radius_m);
    EXPECT_LT(std::fabs(l.velocity.y), 0.05f);
}

TEST(ThrownObjects, ComeToRestOnASolidsTop) {
    // Dropped onto the test level's wall (top at 4 m), as a stone onto the harbour's
    // tank floor on its plinth: it stays where it fell, not pushed out by a face.
    sim::World w(make_test_level());
    w.get<sim::ThrownObjects>().launch({0.22f, 2600.0f, 0.0f}, {152.0f, 7.0f, -12.0f}, {0.0f, 0.0f, 1.0f},
                                       {0.0f, 0.0f, 0.0f});
    for (int i = 0; i < 180; ++i) w.step({});
    const sim::ThrownObject& o = w.get<sim::ThrownObjects>().objects().at(0);
    EXPECT_NEAR(o.position.x, 152.0f, 1e-3f);
    EXPECT_NEAR(o.position.z, -12.0f, 1e-3f);
    EXPECT_NEAR(o.position.y, 4.0f + o.radius_m, 0.02f);
}

TEST(ThrownObjects, ThrowKeysLaunchFromTheVehicle) {
    sim::World w(make_test_level());
    tap(w, Control::ThrowHeavy);
    tap(w, Control::ThrowLight);
    const auto& objs = w.get<sim::ThrownObjects>().objects();
    ASSERT_EQ(objs.size(), 2u);
    EXPECT_TRUE(objs[0].sinks());
    EXPECT_FALSE(objs[1].sinks());
    EXPECT_GT(objs[0].velocity.x, 5.0f);  // thrown forward (+x)
    for (int i = 0; i < 40; ++i) tap(w, Control::ThrowHeavy);
    EXPECT_EQ(w.get<sim::ThrownObjects>().objects().size(), sim::ThrownObjects::kMaxObjects);
}

TEST(Weapon, ShotGrowsIntoABeamAndFades) {
    sim::World w(make_test_level());
    tap(w, Control::Fire);
    const auto& shots = w.get<sim::Weapon>().shots();
    ASSERT_EQ(shots.size(), 1u);
    float early = 0.0f;
    for (const auto& s : shots[0].segments) early += s.length_m;
    run(w, 40, TickInput{});
    float later = 0.0f;
    for (const auto& s : w.get<sim::Weapon>().shots()[0].segments) later += s.length_m;
    EXPECT_GT(later, early + 5.0f);
    for (const auto& s : w.get<sim::Weapon>().shots()[0].segments) {
        EXPECT_NEAR(glm::length(s.direction), 1.0f, 1e-4f);
        EXPECT_GT(s.beam_strength, 0.0f);
    }
    run(w, 200, TickInput{});
    EXPECT_TRUE(w.get<sim::Weapon>().shots().empty());
}

TEST(Weapon, ShotStopsAtAWallAndFliesOverALowOne) {
    // A wall 7 m ahead of the muzzle (the car faces +x, the muzzle is 3 m ahead of it):
    // the head stops at its face. Over a box lower than the shot's path it flies on
    // and lands on the ground further out.
    auto shot_against = [](float top_m) {
        sim::LevelDesc level = make_test_level();
        level.solids.push_back({{10.0f, 0.0f, -20.0f}, {11.0f, top_m, -5.0f}});
        sim::World w(level);
        tap(w, Control::Fire);
        for (int t = 0; t < 90 && !w.get<sim::Weapon>().shots().at(0).hit(); ++t) w.step({});
        return w.get<sim::Weapon>().shots().at(0);
    };
    const sim::Shot wall = shot_against(5.0f);
    ASSERT_TRUE(wall.hit());
    EXPECT_NEAR((wall.origin + wall.direction * wall.hit_distance_m).x, 10.0f, 1e-3f);
    const sim::Shot low = shot_against(1.5f);
    ASSERT_TRUE(low.hit());
    EXPECT_GT((low.origin + low.direction * low.hit_distance_m).x, 20.0f);  // past the box, on the ground
}

TEST(CameraRig, ChaseCameraFollowsBehindAndDriverViewSitsInTheCar) {
    sim::World w(make_test_level());
    run(w, 240, held({Control::Throttle}));
    const sim::CameraView& v = w.get<sim::CameraRig>().view();
    glm::vec3 car = w.get<sim::Car>().position();
    EXPECT_LT(v.eye.x, car.x - 4.0f);  // behind
    EXPECT_GT(v.eye.y, car.y + 1.0f);  // above
    tap(w, Control::Camera, held({Control::Throttle}));
    const sim::CameraView& d = w.get<sim::CameraRig>().view();
    EXPECT_LT(glm::length(d.eye - w.get<sim::Car>().position()), 2.0f);
    EXPECT_GT(d.target.x, d.eye.x);  // looking forward
}

// A busy session: driving, turning, throwing, firing.
TickInput busy_input(uint32_t t) {
    TickInput in;
    in.set(Control::Throttle, (t / 200) % 3 != 2);
    in.set(Control::Brake, (t / 200) % 3 == 2);
    in.set((t / 130) % 2 ? Control::SteerLeft : Control::SteerRight, t % 130 < 50);
    in.set(Control::ThrowHeavy, t % 37 == 3);
    in.set(Control::ThrowLight, t % 41 == 7);
    in.set(Control::Fire, t % 97 == 11);
    return in;
}

std::vector<sim::WorldHash> hashes(int threads, uint32_t ticks) {
    sim::World w(make_test_level(), sim::WorldOptions{threads});
    std::vector<sim::WorldHash> out;
    for (uint32_t t = 0; t < ticks; ++t) {
        w.step(busy_input(t));
        out.push_back(w.hash());
    }
    return out;
}

TEST(Determinism, SameInputsSameHashes) { EXPECT_EQ(hashes(1, 900), hashes(1, 900)); }

TEST(Determinism, SameHashesForAnyThreadCount) {
    auto one = hashes(1, 900);
    EXPECT_EQ(one, hashes(2, 900));
    EXPECT_EQ(one, hashes(3, 900));
}

TEST(Determinism, DifferentInputsDifferentHashes) {
    sim::World a(make_test_level()), b(make_test_level());
    a.step(held({Control::Throttle}));
    b.step(held({Control::Brake}));
    a.step({});
    b.step({});
    EXPECT_NE(a.hash().world, b.hash().world);
    const std::vector<std::string> names = a.subsystem_names();
    const size_t car = size_t(std::find(names.begin(), names.end(), "car") - names.begin());
    ASSERT_LT(car, names.size());
    EXPECT_NE(a.hash().parts[car], b.hash().parts[car]);  // the car moved differently
}

TEST(JobPool, RejectsAbsurdThreadCounts) {
    EXPECT_THROW(sim::JobPool(0), std::invalid_argument);
    EXPECT_THROW(sim::JobPool(1000), std::invalid_argument);
}

TEST(TickInput, QuantiseDropsUnknownBitsAndKeepsSteeringInFullScale) {
    TickInput in{0xffff};
    EXPECT_EQ(sim::quantise(in).held, sim::kAllControls);
    EXPECT_EQ(sim::quantise(TickInput{0, 0, 0, -128}).steer, -sim::kSteerFullScale);
    EXPECT_EQ(sim::quantise(TickInput{0, 255, 7, 127}), (TickInput{0, 255, 7, 127}));
    EXPECT_EQ(sim::control_from_name("fire"), Control::Fire);
    EXPECT_FALSE(sim::control_from_name("jump").has_value());
}

TEST(TickInput, KeysAreFullScaleAndAxesAddTheirSteps) {
    // The keyboard's amounts are exactly those of the held bits alone.
    EXPECT_EQ(sim::throttle_amount(held({Control::Throttle})), 1.0f);
    EXPECT_EQ(sim::brake_amount(held({Control::Brake})), 1.0f);
    EXPECT_EQ(sim::steer_amount(held({Control::SteerLeft})), 1.0f);
    EXPECT_EQ(sim::steer_amount(held({Control::SteerRight})), -1.0f);
    EXPECT_EQ(sim::steer_amount(held({Control::SteerLeft, Control::SteerRight})), 0.0f);
    EXPECT_EQ(sim::throttle_amount(TickInput{}), 0.0f);
    // Analog: in steps of 1/255 and 1/127, full scale exactly 1.
    EXPECT_EQ(sim::throttle_amount(TickInput{0, 255, 0, 0}), 1.0f);
    EXPECT_EQ(sim::throttle_amount(TickInput{0, 51, 0, 0}), 0.2f);
    EXPECT_EQ(sim::brake_amount(TickInput{0, 0, 102, 0}), 0.4f);
    EXPECT_EQ(sim::steer_amount(TickInput{0, 0, 0, -127}), -1.0f);
    EXPECT_FLOAT_EQ(sim::steer_amount(TickInput{0, 0, 0, 64}), 64.0f / 127.0f);
    // A held key wins over a smaller axis; steering adds and stays within -1..1.
    TickInput both = held({Control::Throttle, Control::SteerLeft});
    both.throttle = 10;
    both.steer = 100;
    EXPECT_EQ(sim::throttle_amount(both), 1.0f);
    EXPECT_EQ(sim::steer_amount(both), 1.0f);
    both.steer = -127;
    EXPECT_EQ(sim::steer_amount(both), 0.0f);
}

TEST(Player, DrivesWithAnalogAmounts) {
    sim::World w(make_test_level());
    w.step(TickInput{0, 128, 0, -64});
    const sim::DriveInput d = w.get<sim::Player>().drive_input(sim::Vehicle::Car);
    EXPECT_EQ(d.throttle, 128.0f / 255.0f);
    EXPECT_EQ(d.brake, 0.0f);
    EXPECT_EQ(d.steer, -64.0f / 127.0f);
    // Half throttle accelerates, less than full.
    sim::World half(make_test_level()), full(make_test_level());
    run(half, 120, TickInput{0, 128, 0, 0});
    run(full, 120, held({Control::Throttle}));
    EXPECT_GT(half.get<sim::Car>().speed_mps(), 1.0f);
    EXPECT_LT(half.get<sim::Car>().speed_mps(), full.get<sim::Car>().speed_mps() - 1.0f);
    // Full-scale axes drive exactly as the keys do.
    sim::World keys(make_test_level()), pad(make_test_level());
    run(keys, 200, held({Control::Throttle, Control::SteerLeft}));
    run(pad, 200, TickInput{0, 255, 0, 127});
    EXPECT_EQ(keys.hash().world, pad.hash().world);
}

}  // namespace
