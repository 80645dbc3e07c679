// sim/weapon: shots grow from a ball into a beam and fly, stop and drain where they
// hit the ground or the water, report water impacts for the wave grid to splash, and
// hash the same for any thread count.
#include <cmath>
#include <memory>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "SimTestLevel.h"
#include "sim/water/WaterSim.h"
#include "sim/weapon/Weapon.h"
#include "sim/world/World.h"

namespace {

using sim::Control;
using sim::TickInput;

// The test level with a wave grid over the sea (x, z in [0, 128]) installed as the sea.
struct Harbour {
    sim::World world;
    sim::WaterSim* water = nullptr;
    explicit Harbour(int threads = 1) : world(make_test_level(), {threads}) {
        auto w = std::make_unique<sim::WaterSim>(sim::WaterParams{}, world.level(), world.level().seed);
        water = w.get();
        world.add(std::move(w));
        world.set_sea(water);
    }
    sim::Weapon& weapon() { return world.get<sim::Weapon>(); }
};

glm::vec3 head_of(const sim::Shot& s) {
    const sim::EnergySegment& last = s.segments.back();
    return last.start + last.direction * last.length_m;
}

float shot_length(const sim::Shot& s) {
    float sum = 0.0f;
    for (const sim::EnergySegment& seg : s.segments) sum += seg.length_m;
    return sum;
}

TEST(EnergyWeapon, ShotStartsAsABallAndStretchesIntoAMovingBeam) {
    Harbour h;
    sim::Weapon& weapon = h.weapon();
    weapon.fire({60.0f, 8.0f, 60.0f}, {1.0f, 0.0f, 0.0f});  // level flight high over the sea
    ASSERT_EQ(weapon.shots().size(), 1u);
    EXPECT_LT(shot_length(weapon.shots()[0]), 1e-3f);  // a ball at first
    h.world.step({});
    const glm::vec3 head_early = head_of(weapon.shots()[0]);
    for (int t = 0; t < 45; ++t) h.world.step({});
    const sim::Shot& s = weapon.shots()[0];
    EXPECT_GT(shot_length(s), 12.0f);
    EXPECT_GT(head_of(s).x - head_early.x, 30.0f);  // 45 m/s for 0.75 s
    EXPECT_FALSE(s.hit());
    for (size_t i = 0; i < s.segments.size(); ++i) {
        const sim::EnergySegment& seg = s.segments[i];
        EXPECT_NEAR(glm::length(seg.direction), 1.0f, 1e-4f);
        EXPECT_GT(seg.radius_m, 0.0f);
        EXPECT_EQ(seg.sphere_strength, seg.beam_strength);  // a = b: continuous across plane I
        if (i > 0) {  // a chain: each segment starts where the last ended
            const sim::EnergySegment& prev = s.segments[i - 1];
            EXPECT_LT(glm::length(prev.start + prev.direction * prev.length_m - seg.start), 1e-3f);
        }
    }
    for (int t = 0; t < 150; ++t) h.world.step({});
    EXPECT_TRUE(weapon.shots().empty());  // 2.5 s life
}

TEST(EnergyWeapon, ShotIntoTheWaterStopsThereAndRaisesASplash) {
    Harbour h;
    sim::Weapon& weapon = h.weapon();
    // 10 m above the sea, dipping 1 in 4: hits near x = 20 + 40 = 60, z = 64.
    weapon.fire({20.0f, 10.0f, 64.0f}, {4.0f, -1.0f, 0.0f});
    bool splashed = false;
    size_t entries = 0;
    glm::vec3 entry{0.0f};
    for (int t = 0; t < 90 && !splashed; ++t) {
        h.world.step({});
        entries += h.world.events().water_entries.size();
        if (!h.world.events().water_entries.empty()) entry = h.world.events().water_entries[0].position;
        splashed = !h.water->splashes().empty();
    }
    ASSERT_TRUE(splashed);
    EXPECT_EQ(entries, 1u);
    EXPECT_NEAR(entry.x, 60.0f, 0.5f);
    EXPECT_NEAR(entry.z, 64.0f, 1e-3f);
    EXPECT_NEAR(entry.y, 0.0f, 0.05f);
    EXPECT_NEAR(h.water->splashes()[0].position.x, 60.0f, 0.5f);
    ASSERT_EQ(weapon.shots().size(), 1u);
    EXPECT_TRUE(weapon.shots()[0].hit());
    // The head stays at the impact; the tail drains into it and the light fades.
    for (int t = 0; t < 20; ++t) h.world.step({});
    ASSERT_EQ(weapon.shots().size(), 1u);
    EXPECT_NEAR(head_of(weapon.shots()[0]).x, 60.0f, 0.5f);
    EXPECT_LT(shot_length(weapon.shots()[0]), 0.5f);
    EXPECT_LT(weapon.shots()[0].segments[0].beam_strength, weapon.params().strength);
    for (int t = 0; t < 20; ++t) h.world.step({});
    EXPECT_TRUE(weapon.shots().empty());  // gone fade_s after the hit
    EXPECT_GT(std::fabs(h.water->grid().sample({60.0f, 64.0f})), 1e-4f);  // the grid was pushed
}

TEST(EnergyWeapon, ShotIntoTheGroundStopsWithoutASplash) {
    Harbour h;
    sim::Weapon& weapon = h.weapon();
    weapon.fire({0.0f, 5.0f, -40.0f}, {4.0f, -1.0f, 0.0f});  // over land (z < 0, ground at 1 m)
    size_t entries = 0;
    for (int t = 0; t < 40; ++t) {
        h.world.step({});
        entries += h.world.events().water_entries.size();
    }
    EXPECT_EQ(entries, 0u);
    ASSERT_EQ(weapon.shots().size(), 1u);
    EXPECT_TRUE(weapon.shots()[0].hit());
    EXPECT_NEAR(head_of(weapon.shots()[0]).y, 1.0f, 0.05f);  // on the ground
}

TEST(EnergyWeapon, FiredFromTheCarDipsBelowTheHeadingAndHashesTheSameOnTwoThreads) {
    sim::World one(make_test_level(), {1}), two(make_test_level(), {2});
    for (int t = 0; t < 200; ++t) {
        TickInput in;
        in.set(Control::Throttle, true);
        in.set(Control::Fire, t % 20 == 0);
        one.step(in);
        two.step(in);
        ASSERT_EQ(one.hash().world, two.hash().world) << "tick " << t;
    }
    const auto& shots = one.get<sim::Weapon>().shots();
    ASSERT_FALSE(shots.empty());
    EXPECT_LE(shots.size(), sim::Weapon::kMaxShots);
    EXPECT_NEAR(shots.back().direction.y, -std::sin(one.get<sim::Weapon>().params().dip_rad), 1e-5f);
    // Firing changes the weapon's hash: shots are part of the world state.
    sim::World quiet(make_test_level());
    for (int t = 0; t < 200; ++t) {
        TickInput in;
        in.set(Control::Throttle, true);
        quiet.step(in);
    }
    EXPECT_NE(quiet.hash().world, one.hash().world);
}

}  // namespace
