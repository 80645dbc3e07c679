// sim/weapon: shots grow from a ball into a beam and fly, stop and drain where they
// hit the ground or the water, report water impacts for the wave grid to splash, and
// hash the same for any thread count.
#include <algorithm>
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
    explicit Harbour(int threads = 1)
        : world(make_test_level(), sim::standard_subsystems_with_water({}), {threads}),
          water(&world.get<sim::WaterSim>()) {}
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

// How far the chain's inner joints stand off the straight line from its tail to its head.
float sway_of(const sim::Shot& s) {
    const glm::vec3 tail = s.segments.front().start, axis = glm::normalize(head_of(s) - tail);
    float most = 0.0f;
    for (size_t i = 1; i < s.segments.size(); ++i) {
        const glm::vec3 v = s.segments[i].start - tail;
        most = std::max(most, glm::length(v - glm::dot(v, axis) * axis));
    }
    return most;
}

TEST(EnergyWeapon, TwoShotsFlyAtOnceEachAsIfAlone) {
    Harbour both, alone;
    // Level flight high over the sea, one along x and one along z, fired 10 ticks apart.
    both.weapon().fire({40.0f, 9.0f, 40.0f}, {1.0f, 0.0f, 0.0f});
    alone.weapon().fire({40.0f, 9.0f, 40.0f}, {1.0f, 0.0f, 0.0f});
    for (int t = 0; t < 10; ++t) {
        both.world.step({});
        alone.world.step({});
    }
    both.weapon().fire({20.0f, 7.0f, 20.0f}, {0.0f, 0.0f, 1.0f});
    for (int t = 0; t < 40; ++t) {
        both.world.step({});
        alone.world.step({});
    }
    const std::vector<sim::Shot>& shots = both.weapon().shots();
    ASSERT_EQ(shots.size(), 2u);
    EXPECT_EQ(shots[0].age_ticks, 50u);
    EXPECT_EQ(shots[1].age_ticks, 40u);
    EXPECT_FALSE(shots[0].hit() || shots[1].hit());
    EXPECT_GT(head_of(shots[0]).x - 40.0f, 30.0f);  // 45 m/s for 50 ticks
    EXPECT_GT(head_of(shots[1]).z - 20.0f, 25.0f);  // for 40 ticks
    EXPECT_NEAR(head_of(shots[1]).x, 20.0f, 1.0f);  // each on its own line
    // The first shot is where it would be without the second: shots do not interact.
    ASSERT_EQ(alone.weapon().shots().size(), 1u);
    for (size_t i = 0; i < shots[0].segments.size(); ++i) {
        EXPECT_EQ(shots[0].segments[i].start, alone.weapon().shots()[0].segments[i].start);
        EXPECT_EQ(shots[0].segments[i].beam_strength, alone.weapon().shots()[0].segments[i].beam_strength);
    }
    EXPECT_NE(both.world.hash().world, alone.world.hash().world);
}

TEST(EnergyWeapon, GrownBeamSwaysOffItsLineAndFadesBeforeItsEnd) {
    Harbour h;
    sim::Weapon& weapon = h.weapon();
    const sim::WeaponParams& p = weapon.params();
    weapon.fire({40.0f, 9.0f, 60.0f}, {1.0f, 0.0f, 0.0f});
    const int life_ticks = int(p.life_s * 60.0f + 0.5f), fade_start = int((p.life_s - p.fade_s) * 60.0f);
    float last_strength = p.strength;
    int faded_ticks = 0;
    for (int t = 1; t < life_ticks; ++t) {
        h.world.step({});
        ASSERT_EQ(weapon.shots().size(), 1u) << "tick " << t;
        const sim::Shot& s = weapon.shots()[0];
        ASSERT_FALSE(s.hit());
        const float strength = s.segments[0].beam_strength;
        if (t >= 45 && t < fade_start) {  // grown, in mid-flight
            // The three inner joints sway out of phase: some joint is always well off the line.
            EXPECT_GT(sway_of(s), 0.5f * p.sway_m) << "tick " << t;
            EXPECT_LE(sway_of(s), 1.2f * p.sway_m) << "tick " << t;
            EXPECT_EQ(strength, p.strength);
        }
        if (t > fade_start + 1) {
            EXPECT_LT(strength, last_strength) << "tick " << t;  // drops every tick of the fade
            EXPECT_GT(strength, 0.0f);
            ++faded_ticks;
        }
        last_strength = strength;
    }
    EXPECT_GT(faded_ticks, 30);
    EXPECT_LT(last_strength, 0.05f * p.strength);  // nearly dark on its last tick
    h.world.step({});
    EXPECT_TRUE(weapon.shots().empty());
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
    sim::World one(make_test_level(), sim::WorldOptions{1}), two(make_test_level(), sim::WorldOptions{2});
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
