// The objectives (sim/objectives): gate crossings and lap timing on a synthetic course,
// targets hit by a stone and by a shot, the lap replays/harbour_drive drives and the lap
// and hits of replays/harbour_goals.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "game/level/LevelLoader.h"
#include "game/play/ObjectiveHud.h"
#include "game/replay/ObjectiveSummary.h"
#include "game/replay/InputScript.h"
#include "sim/core/DetMath.h"
#include "sim/objectives/Course.h"
#include "sim/objectives/Objectives.h"
#include "sim/objectives/Targets.h"
#include "sim/objects/ThrownObjects.h"
#include "sim/weapon/Weapon.h"
#include "sim/world/World.h"

namespace {

constexpr float kQuarterTurn = 1.57079632679f;
// The lap replays/harbour_drive.script drives, in ticks (`replay --check` prints it).
constexpr uint64_t kHarbourDriveLapTicks = 1308;
// The boat's lap replays/harbour_goals.script drives, and the ticks its shot lights a
// crate and its stone hits a buoy.
constexpr uint64_t kHarbourGoalsLapTicks = 816;
constexpr uint64_t kHarbourGoalsCrateHitTick = 499;
constexpr uint64_t kHarbourGoalsBuoyHitTick = 1631;

// A square of four gates 20 m apart, driven anticlockwise seen from above (+x, -z, -x, +z).
sim::CourseDesc square_course() {
    sim::CourseDesc c;
    c.name = "square";
    c.gates = {{{0.0f, 0.0f}, 0.0f, 6.0f},
               {{20.0f, -20.0f}, kQuarterTurn, 6.0f},
               {{0.0f, -40.0f}, 2.0f * kQuarterTurn, 6.0f},
               {{-20.0f, -20.0f}, 3.0f * kQuarterTurn, 6.0f}};
    return c;
}

// Moves across gate `g` of the square the right way (or backwards): from 1 m behind it to
// 1 m past it along its heading.
void pass(sim::Course& course, size_t g, uint64_t ticks, bool backwards = false) {
    const sim::GateDesc& gate = course.desc().gates[g];
    float s = 0.0f, c = 0.0f;
    sim::det::sincos(gate.heading_rad, s, c);
    const glm::vec2 ahead(c, -s);
    const glm::vec2 behind = gate.centre_xz - ahead, past = gate.centre_xz + ahead;
    if (backwards) course.advance(past, behind, ticks);
    else course.advance(behind, past, ticks);
}

TEST(Course, GatePostsStandAcrossTheHeading) {
    const sim::GatePosts p = sim::gate_posts({{10.0f, -10.0f}, 0.0f, 8.0f});
    // Facing +x, the left is -z.
    EXPECT_FLOAT_EQ(p.left.x, 10.0f);
    EXPECT_FLOAT_EQ(p.left.y, -14.0f);
    EXPECT_FLOAT_EQ(p.right.y, -6.0f);
}

TEST(Course, CrossingCountsOnlyBetweenThePostsAndForwards) {
    const sim::GatePosts gate = sim::gate_posts({{0.0f, 0.0f}, 0.0f, 4.0f});  // posts at z -2 and 2
    EXPECT_TRUE(sim::crosses_gate(gate, {-0.5f, 0.0f}, {0.5f, 0.0f}));
    EXPECT_TRUE(sim::crosses_gate(gate, {-0.5f, 1.9f}, {0.5f, 1.9f}));
    EXPECT_TRUE(sim::crosses_gate(gate, {-0.5f, 0.0f}, {0.0f, 0.0f}));    // reaching the line counts
    EXPECT_FALSE(sim::crosses_gate(gate, {0.0f, 0.0f}, {0.5f, 0.0f}));    // leaving it does not: no double count
    EXPECT_FALSE(sim::crosses_gate(gate, {0.5f, 0.0f}, {-0.5f, 0.0f}));   // backwards
    EXPECT_FALSE(sim::crosses_gate(gate, {-0.5f, 2.5f}, {0.5f, 2.5f}));   // outside the posts
    EXPECT_FALSE(sim::crosses_gate(gate, {-0.5f, -2.5f}, {0.5f, -2.5f}));
    EXPECT_FALSE(sim::crosses_gate(gate, {-1.0f, 0.0f}, {-0.5f, 0.0f}));  // short of it
    // A diagonal move that crosses the line inside the posts, though both ends lie beyond them.
    EXPECT_TRUE(sim::crosses_gate(gate, {-1.0f, -3.0f}, {1.0f, 3.0f}));
}

TEST(Course, ALapIsEveryGateInOrderBackToTheStart) {
    sim::Course course(square_course());
    EXPECT_FALSE(course.lap_running());
    pass(course, 0, 100);
    ASSERT_TRUE(course.lap_running());
    EXPECT_EQ(course.next_gate(), 1u);
    EXPECT_EQ(course.lap_ticks(160), 60u);
    pass(course, 1, 200);
    pass(course, 2, 300);
    pass(course, 3, 400);
    EXPECT_EQ(course.laps(), 0u);
    EXPECT_EQ(course.next_gate(), 0u);
    pass(course, 0, 500);
    EXPECT_EQ(course.laps(), 1u);
    EXPECT_EQ(course.last_lap_ticks(), 400u);
    EXPECT_EQ(course.best_lap_ticks(), 400u);
    EXPECT_EQ(course.lap_ticks(500), 0u);  // the next lap started at the line

    // A slower lap keeps the best; a faster one replaces it.
    for (size_t g : {1, 2, 3}) pass(course, g, 500 + 150 * g);
    pass(course, 0, 1000);
    EXPECT_EQ(course.laps(), 2u);
    EXPECT_EQ(course.last_lap_ticks(), 500u);
    EXPECT_EQ(course.best_lap_ticks(), 400u);
    for (size_t g : {1, 2, 3}) pass(course, g, 1000 + 50 * g);
    pass(course, 0, 1300);
    EXPECT_EQ(course.best_lap_ticks(), 300u);
}

TEST(Course, GatesOutOfOrderOrBackwardsDoNotCount) {
    sim::Course course(square_course());
    pass(course, 1, 10);  // not started: only the start line counts
    EXPECT_FALSE(course.lap_running());
    pass(course, 0, 20);
    pass(course, 2, 30);  // skipping gate 1
    pass(course, 3, 40);
    EXPECT_EQ(course.next_gate(), 1u);
    pass(course, 1, 50, true);  // backwards
    EXPECT_EQ(course.next_gate(), 1u);
    pass(course, 0, 60);  // the start line again, without the lap: neither a lap nor a restart
    EXPECT_EQ(course.laps(), 0u);
    EXPECT_EQ(course.lap_ticks(60), 40u);
    pass(course, 1, 70);
    pass(course, 2, 80);
    pass(course, 3, 90);
    pass(course, 0, 100);
    EXPECT_EQ(course.laps(), 1u);
    EXPECT_EQ(course.last_lap_ticks(), 80u);
}

TEST(Course, ALapIsCountedOnce) {
    sim::Course course(square_course());
    for (size_t g : {0, 1, 2, 3, 0}) pass(course, g, 10 * (g + 1));
    ASSERT_EQ(course.laps(), 1u);
    // Lingering on the finish line, or crossing it back and forth, adds no lap.
    pass(course, 0, 70, true);
    pass(course, 0, 80);
    course.advance({0.0f, 0.0f}, {0.0f, 0.0f}, 90);
    EXPECT_EQ(course.laps(), 1u);
    EXPECT_EQ(course.next_gate(), 1u);
}

// ---- targets ------------------------------------------------------------------------------

sim::TargetDesc crate_at(glm::vec3 p) { return {sim::TargetKind::Crate, p, 0.6f}; }

TEST(Targets, AStoneTouchingATargetHitsItOnce) {
    sim::Targets targets({crate_at({0.0f, 1.0f, 0.0f}), crate_at({10.0f, 1.0f, 0.0f})});
    sim::ThrownObject stone;
    stone.radius_m = sim::ThrownObjects::kHeavy.radius_m;
    stone.position = {0.0f, 1.0f, 0.9f};  // 0.9 m away: beyond 0.6 + 0.22
    targets.hit_by({stone}, {}, 5);
    EXPECT_EQ(targets.hit_count(), 0u);
    stone.position = {0.0f, 1.0f, 0.8f};
    targets.hit_by({stone}, {}, 6);
    ASSERT_EQ(targets.hit_count(), 1u);
    EXPECT_EQ(targets.states()[0].hit_by, sim::HitBy::Object);
    EXPECT_EQ(targets.states()[0].hit_at_ticks, 6u);
    EXPECT_FALSE(targets.states()[1].hit());
    targets.hit_by({stone}, {}, 7);  // still touching: no second hit
    EXPECT_EQ(targets.states()[0].hit_at_ticks, 6u);
    EXPECT_EQ(targets.hit_count(), 1u);
}

TEST(Targets, AShotPassingATargetHitsIt) {
    sim::Targets targets({crate_at({0.0f, 1.0f, 0.0f}), crate_at({0.0f, 1.0f, 5.0f})});
    sim::Shot shot;
    for (int i = 0; i < sim::Shot::kSegments; ++i) {
        sim::EnergySegment& s = shot.segments[size_t(i)];
        s.start = {-8.0f + 4.0f * float(i), 1.5f, 0.0f};  // along x, 0.5 m above the first crate
        s.direction = {1.0f, 0.0f, 0.0f};
        s.length_m = 4.0f;
        s.beam_strength = s.sphere_strength = 0.1f;
    }
    sim::Shot spent = shot;
    for (sim::EnergySegment& s : spent.segments) s.beam_strength = s.sphere_strength = 0.0f;
    targets.hit_by({}, {spent}, 3);  // a shot faded out lights nothing
    EXPECT_EQ(targets.hit_count(), 0u);
    targets.hit_by({}, {shot}, 4);
    ASSERT_EQ(targets.hit_count(), 1u);
    EXPECT_EQ(targets.states()[0].hit_by, sim::HitBy::Shot);
    EXPECT_FALSE(targets.states()[1].hit());
}

// In the world: a stone thrown from the car at a crate in front of it, then a shot at a
// crate further on; the hits are in the objectives' hash, the same for 1 and 2 threads.
uint64_t throw_and_fire(int threads, size_t& hits) {
    sim::LevelDesc level = game::load_level("harbour").sim;
    level.objectives.courses.clear();
    // The car spawns at (-20, 1.2, -10) facing +x: the stone comes down about 12 m on,
    // the shot flies low along the road and lands about 30 m on.
    level.objectives.targets = {crate_at({-8.0f, 1.8f, -10.0f}), crate_at({2.0f, 2.0f, -10.0f})};
    sim::World world(level, sim::WorldOptions{threads});
    sim::TickInput none, stone, fire;
    stone.set(sim::Control::ThrowHeavy, true);
    fire.set(sim::Control::Fire, true);
    const sim::Objectives& objectives = world.get<sim::Objectives>();
    world.step(stone);
    for (int i = 0; i < 90; ++i) world.step(none);
    EXPECT_TRUE(objectives.targets().states()[0].hit()) << "the stone";
    EXPECT_EQ(objectives.targets().states()[0].hit_by, sim::HitBy::Object);
    world.step(fire);
    for (int i = 0; i < 60; ++i) world.step(none);
    EXPECT_EQ(objectives.targets().states()[1].hit_by, sim::HitBy::Shot) << "the shot";
    hits = objectives.targets().hit_count();
    return world.hash().world;
}

TEST(Targets, AStoneAndAShotFromTheCarHitTheirCratesTheSameForAnyThreadCount) {
    size_t hits1 = 0, hits2 = 0;
    const uint64_t one = throw_and_fire(1, hits1);
    const uint64_t two = throw_and_fire(2, hits2);
    EXPECT_EQ(hits1, 2u);
    EXPECT_EQ(one, two);
}

// ---- the bundled replay -------------------------------------------------------------------

// replays/harbour_drive drives one lap of the harbour's car course (the objective the
// README describes); the lap's time is what `replay --check` prints.
TEST(HarbourDriveScript, DrivesOneLapOfTheCarCourse) {
    const game::InputScript script =
        game::load_script(std::string(SPINDRIFT_TEST_DATA) + "/../../replays/harbour_drive.script");
    sim::World world(game::load_level(script.level).sim);
    const sim::Course* course = world.get<sim::Objectives>().course_for(sim::CourseVehicle::Car);
    ASSERT_NE(course, nullptr);
    for (uint32_t t = 0; t < script.end_tick; ++t) world.step(script.inputs[t]);
    EXPECT_EQ(course->laps(), 1u);
    ASSERT_TRUE(course->best_lap_ticks().has_value());
    EXPECT_EQ(*course->best_lap_ticks(), kHarbourDriveLapTicks);
    const std::vector<std::string> summary = game::objective_summary_lines(world);
    ASSERT_FALSE(summary.empty());
    EXPECT_EQ(summary[0], "course quay (car): 1 lap, last " + game::lap_time_text(kHarbourDriveLapTicks) + ", best " +
                              game::lap_time_text(kHarbourDriveLapTicks) + " (" + std::to_string(kHarbourDriveLapTicks) +
                              " ticks)");
}

// replays/harbour_goals lights a crate with a shot from the car, gets the boat round its
// course and hits a buoy with a stone from the boat.
TEST(HarbourGoalsScript, LapsTheBoatCourseAndHitsACrateAndABuoy) {
    const game::InputScript script =
        game::load_script(std::string(SPINDRIFT_TEST_DATA) + "/../../replays/harbour_goals.script");
    sim::World world(game::load_level(script.level).sim);
    const sim::Objectives& objectives = world.get<sim::Objectives>();
    const sim::Course* course = objectives.course_for(sim::CourseVehicle::Boat);
    ASSERT_NE(course, nullptr);
    for (uint32_t t = 0; t < script.end_tick; ++t) world.step(script.inputs[t]);
    EXPECT_EQ(course->laps(), 1u);
    ASSERT_TRUE(course->best_lap_ticks().has_value());
    EXPECT_EQ(*course->best_lap_ticks(), kHarbourGoalsLapTicks);
    // Exactly one crate, by the shot, and one buoy, by the stone.
    std::vector<std::string> hits;
    for (const sim::TargetState& t : objectives.targets().states())
        if (t.hit())
            hits.push_back(std::string(t.desc.kind == sim::TargetKind::Crate ? "crate" : "buoy") + " by " +
                           (t.hit_by == sim::HitBy::Shot ? "shot" : "object") + " at " + std::to_string(t.hit_at_ticks));
    EXPECT_EQ(hits, (std::vector<std::string>{"crate by shot at " + std::to_string(kHarbourGoalsCrateHitTick),
                                              "buoy by object at " + std::to_string(kHarbourGoalsBuoyHitTick)}));
    const std::vector<std::string> summary = game::objective_summary_lines(world);
    ASSERT_EQ(summary.size(), 3u);
    EXPECT_EQ(summary[1], "course pier (boat): 1 lap, last " + game::lap_time_text(kHarbourGoalsLapTicks) + ", best " +
                              game::lap_time_text(kHarbourGoalsLapTicks) + " (" + std::to_string(kHarbourGoalsLapTicks) +
                              " ticks)");
    EXPECT_EQ(summary[2], "targets hit 2 of 6");
}

TEST(ObjectiveHud, LapTimesInMinutesSecondsAndHundredths) {
    EXPECT_EQ(game::lap_time_text(0), "0:00.00");
    EXPECT_EQ(game::lap_time_text(1308), "0:21.80");
    EXPECT_EQ(game::lap_time_text(61), "0:01.02");  // 1.0167 s, rounded
    EXPECT_EQ(game::lap_time_text(60 * 75), "1:15.00");
}

}  // namespace
