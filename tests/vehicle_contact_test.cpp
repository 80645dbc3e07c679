// Vehicles against everything they can run into: walls, the quay edge, bollards, lamp
// posts, kerbs and the world's border, at several angles and speeds. Whatever they hit,
// steering away or reversing frees them within a second, and they never end up inside
// a solid or in the sea.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "SimInput.h"
#include "sim/player/Player.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/world/World.h"

namespace {

using sim::Control;
using sim::TickInput;

constexpr float kPi = 3.14159265f;
constexpr int kOneSecond = sim::kTickRateHz;

// Flat land (a road everywhere) for z < 0, the sea beyond; no obstacles yet.
sim::LevelDesc open_level() {
    sim::LevelDesc l;
    l.id = "contact";
    l.seed = 3;
    l.half_extent_m = 200.0f;
    l.land_height_m = 1.0f;
    l.shore_z_m = 0.0f;
    l.sea_level_m = 0.0f;
    l.seabed_m = -6.0f;
    l.roads.push_back({{-200.0f, -200.0f}, {200.0f, 200.0f}});
    l.car_spawn = {{0.0f, 1.0f, -100.0f}, 0.0f};
    l.boat_spawn = {{-150.0f, 0.0f, 150.0f}, 0.0f};
    return l;
}

float box_distance(const sim::Aabb& b, glm::vec2 p) {
    float dx = std::max({b.min.x - p.x, 0.0f, p.x - b.max.x});
    float dz = std::max({b.min.z - p.y, 0.0f, p.y - b.max.z});
    return std::sqrt(dx * dx + dz * dz);
}

// One kind of obstacle: its level, a point on it the car aims at, the outward normal
// there (towards where the car comes from), and the car's distance from it. A post is
// met off the car's middle when the car comes at an angle: a glancing blow.
struct Obstacle {
    std::string name;
    sim::LevelDesc level;
    glm::vec2 aim;
    glm::vec2 normal;
    std::function<float(glm::vec2)> distance;
    float glancing_m = 0.0f;
};

Obstacle wall() {
    sim::LevelDesc l = open_level();
    sim::Aabb box{{-60.0f, 1.0f, -60.0f}, {60.0f, 5.0f, -50.0f}};
    l.solids.push_back(box);
    return {"wall", l, {0.0f, -60.0f}, {0.0f, -1.0f}, [box](glm::vec2 p) { return box_distance(box, p); }};
}

Obstacle quay() {
    return {"quay", open_level(), {0.0f, 0.0f}, {0.0f, -1.0f}, [](glm::vec2 p) { return -p.y; }};
}

// The harbour's row of bollards half a metre from the quay edge, 8 m apart.
Obstacle bollards() {
    sim::LevelDesc l = open_level();
    for (float x = -48.0f; x <= 48.0f; x += 8.0f)
        l.solids.push_back({{x - 0.19f, 1.0f, -0.69f}, {x + 0.19f, 1.64f, -0.31f}});
    sim::Aabb middle = l.solids[6];
    return {"bollard", l, {0.0f, -0.5f}, {0.0f, -1.0f}, [middle](glm::vec2 p) { return box_distance(middle, p); },
            0.7f};
}

Obstacle lamp_post() {
    sim::LevelDesc l = open_level();
    sim::Aabb pole{{-0.13f, 1.0f, -50.13f}, {0.13f, 7.0f, -49.87f}};
    l.solids.push_back(pole);
    return {"lamp post", l, {0.0f, -50.0f}, {0.0f, -1.0f}, [pole](glm::vec2 p) { return box_distance(pole, p); },
            0.7f};
}

Obstacle world_border() {
    return {"world border", open_level(), {200.0f, -100.0f}, {-1.0f, 0.0f}, [](glm::vec2 p) { return 200.0f - p.x; }};
}

float heading_of(glm::vec2 dir) { return std::atan2(-dir.y, dir.x); }  // Pose: 0 faces +x, turning to -z

// Distance a car covers from rest while reaching `speed`, and how many ticks that takes.
std::pair<float, int> run_up(float speed) {
    sim::World w(open_level());
    const sim::Car& car = w.get<sim::Car>();
    int ticks = 0;
    while (car.speed_mps() < speed) {
        w.step(held({Control::Throttle}));
        ++ticks;
    }
    return {car.position().x, ticks};
}

// Throttle only below `speed`: a driver holding a steady pace.
TickInput cruise(const sim::Car& car, float speed) {
    return car.speed_mps() < speed ? held({Control::Throttle}) : TickInput{};
}

// Whether the car's body overlaps a solid by more than `slack` or a wheel hangs over the
// sea or out of the world.
std::string trapped_where(const sim::World& w) {
    const sim::Car& car = w.get<sim::Car>();
    const sim::Terrain& terrain = w.terrain();
    const sim::CarParams& p = car.params();
    glm::vec3 f = car.pose().forward_flat(), r = car.pose().right_flat(), c = car.position();
    const float slack = 0.25f;
    for (float along : {p.cg_to_front_m, -p.cg_to_rear_m}) {
        glm::vec2 axle(c.x + f.x * along, c.z + f.z * along);
        if (terrain.resolve_solids(axle, p.radius_m - slack, c.y + 0.25f, c.y + p.height_m))
            return "inside a solid";
        for (float side : {-0.8f, 0.8f}) {
            glm::vec2 wheel(c.x + f.x * along + r.x * side, c.z + f.z * along + r.z * side);
            if (!terrain.inside_world(wheel)) return "out of the world";
            if (terrain.support_height(wheel, c.y) < terrain.level().sea_level_m) return "over the sea";
        }
    }
    return "";
}

enum class Escape { SteerAway, Reverse };

// Drives into `o` at `angle_deg` to its surface (90: head on) at `speed`, holds the
// throttle against it for a second, then escapes. Returns what went wrong, or "".
std::string drive_into(const Obstacle& o, float angle_deg, float speed, Escape escape) {
    auto [run, run_ticks] = run_up(speed);
    // Travel at `angle_deg` to the surface, coming from the -x side along it.
    float a = angle_deg * kPi / 180.0f;
    glm::vec2 tangent(-o.normal.y, o.normal.x);
    if (tangent.x < 0.0f || (tangent.x == 0.0f && tangent.y < 0.0f)) tangent = -tangent;
    glm::vec2 dir = -o.normal * std::sin(a) + tangent * std::cos(a);
    const float lead_m = 6.0f;  // cruising before the nose meets it
    glm::vec2 right(-dir.y, dir.x);
    glm::vec2 start = o.aim - dir * (run + lead_m) - right * (escape == Escape::SteerAway ? o.glancing_m : 0.0f);
    sim::LevelDesc level = o.level;
    level.car_spawn = {{start.x, level.land_height_m, start.y}, heading_of(dir)};
    sim::World w(level);
    const sim::Car& car = w.get<sim::Car>();
    auto distance = [&] { return o.distance({car.position().x, car.position().z}); };

    float closest = distance();
    int approach = run_ticks + int(std::ceil((lead_m + 4.0f) / speed * kOneSecond));
    for (int t = 0; t < approach + kOneSecond; ++t) {
        w.step(t < approach ? cruise(car, speed) : held({Control::Throttle}));
        closest = std::min(closest, distance());
        if (std::string where = trapped_where(w); !where.empty()) return "while driving in: " + where;
    }
    if (closest > 2.6f) return "never reached it (closest " + std::to_string(closest) + " m)";

    // Steering away turns the nose towards the obstacle's normal; reversing backs
    // straight out.
    TickInput in = held({Control::Brake});
    if (escape == Escape::SteerAway) {
        glm::vec3 f = car.pose().forward_flat();
        glm::vec2 turn_left_dir(f.z, -f.x);  // how the nose moves when the heading grows
        bool left = (turn_left_dir.x * o.normal.x + turn_left_dir.y * o.normal.y) >= 0.0f;
        in = held({Control::Throttle, left ? Control::SteerLeft : Control::SteerRight});
    }

    // Reversing starts once the brakes have stopped the car; the second runs from there.
    int braking = 0;
    while (escape == Escape::Reverse && car.speed_mps() > 0.05f) {
        w.step(in);
        if (++braking > 5 * kOneSecond) return "still rolling forwards after 5 s of brake";
        if (std::string where = trapped_where(w); !where.empty()) return "while braking: " + where;
    }
    // Free: moving, and either getting away from it or already well past it (a post is
    // passed close by before the distance grows).
    std::vector<float> d{distance()};
    const glm::vec3 from = car.position();
    for (int t = 1; t <= kOneSecond; ++t) {
        w.step(in);
        d.push_back(distance());
        if (std::string where = trapped_where(w); !where.empty()) return "while escaping: " + where;
        glm::vec3 v = car.velocity(), moved = car.position() - from;
        bool moving = std::sqrt(v.x * v.x + v.z * v.z) > 0.5f;
        bool leaving = t >= 10 && d[size_t(t)] > d[size_t(t - 10)] + 0.05f;
        bool past = std::sqrt(moved.x * moved.x + moved.z * moved.z) > 1.5f;
        if (moving && (leaving || past)) return "";
    }
    return "not free a second after escaping: speed " + std::to_string(car.speed_mps()) + " m/s, " +
           std::to_string(distance()) + " m from it";
}

// Nosed in steeply a car backs out, as a driver would; after a glancing blow it steers
// away (backing out along an edge it lies against would not take it away from it).
void expect_never_trapped(const Obstacle& o) {
    for (float angle : {90.0f, 60.0f, 30.0f})
        for (float speed : {5.0f, 15.0f, 25.0f}) {
            Escape e = angle > 45.0f ? Escape::Reverse : Escape::SteerAway;
            EXPECT_EQ(drive_into(o, angle, speed, e), "")
                << o.name << " at " << angle << " degrees, " << speed << " m/s, "
                << (e == Escape::Reverse ? "reversing" : "steering away");
        }
}

TEST(VehicleContact, SlidesOffAWall) { expect_never_trapped(wall()); }

TEST(VehicleContact, SlidesAlongTheQuayEdge) { expect_never_trapped(quay()); }

TEST(VehicleContact, SlidesOffBollardsByTheWater) {
    expect_never_trapped(bollards());
}

// The trap a player met: nosed in at about 0.5 rad to a bollard right at the quay edge
// with the throttle held, the bollard against the nose and the quay edge under its
// right front corner. Reversing always got out; full lock away from the water with the
// throttle must too: the nose scrubs round along the bollard and the car drives off.
TEST(VehicleContact, SteersOffABollardAtTheQuayEdge) {
    const Obstacle o = bollards();
    const sim::Aabb bollard = o.level.solids[6];
    for (float off : {0.0f, 0.5f, 1.0f}) {  // how far right of the bollard the car aims
        const float a = 0.5f;
        const glm::vec2 dir(std::cos(a), std::sin(a));  // along the quay and out towards the sea
        const glm::vec2 right(-dir.y, dir.x);
        const glm::vec2 start = glm::vec2(0.0f, -0.5f) - dir * 12.0f + right * off;
        sim::LevelDesc level = o.level;
        level.car_spawn = {{start.x, level.land_height_m, start.y}, heading_of(dir)};
        sim::World w(level);
        const sim::Car& car = w.get<sim::Car>();
        // How far the nose (the front axle's collision circle) is from the bollard.
        auto nose_gap = [&] {
            glm::vec3 f = car.pose().forward_flat(), c = car.position();
            glm::vec2 nose(c.x + f.x * car.params().cg_to_front_m, c.z + f.z * car.params().cg_to_front_m);
            return box_distance(bollard, nose) - car.params().radius_m;
        };
        for (int t = 0; t < 4 * kOneSecond; ++t) w.step(cruise(car, 4.0f));
        run(w, kOneSecond, held({Control::Throttle}));
        ASSERT_LT(nose_gap(), 0.05f) << off << " m right: not nosed in to the bollard";
        ASSERT_LT(car.speed_mps(), 0.1f) << off << " m right: not held by the bollard";
        bool free = false;
        for (int t = 0; t < kOneSecond && !free; ++t) {
            w.step(held({Control::Throttle, Control::SteerLeft}));
            ASSERT_EQ(trapped_where(w), "") << off << " m right";
            free = car.speed_mps() > 0.5f && nose_gap() > 0.05f;
        }
        EXPECT_TRUE(free) << off << " m right: a second of full lock and throttle later, "
                          << car.speed_mps() << " m/s with the nose " << nose_gap() << " m off the bollard";
    }
}

TEST(VehicleContact, SlidesOffALampPost) {
    expect_never_trapped(lamp_post());
}

TEST(VehicleContact, SlidesAlongTheWorldBorder) {
    expect_never_trapped(world_border());
}

// The boat against the quay wall and a piling, the same way: run-up out at sea, with the
// car parked on a deck close by so that the player can step across. Boats answer the
// helm slower than cars answer the wheel: two seconds to get away.
std::string sail_into(bool piling, float angle_deg, float speed) {
    sim::LevelDesc l = open_level();
    const glm::vec2 aim = piling ? glm::vec2(0.0f, 40.0f) : glm::vec2(0.0f, 0.0f);
    sim::Aabb post{{-0.2f, -7.0f, 39.8f}, {0.2f, 2.0f, 40.2f}};
    if (piling) l.solids.push_back(post);
    auto distance = [&](glm::vec2 p) { return piling ? box_distance(post, p) : p.y; };
    const glm::vec2 normal(0.0f, 1.0f);  // out to sea

    // Run-up: how far the boat goes before it makes `speed`.
    float run = 0.0f;
    int run_ticks = 0;
    {
        sim::LevelDesc open = open_level();
        open.boat_spawn = {{0.0f, 0.0f, 100.0f}, 0.0f};
        open.car_spawn = {{0.0f, 1.0f, 108.0f}, 0.0f};
        open.decks.push_back({{-5.0f, 0.6f, 104.0f}, {5.0f, 1.0f, 112.0f}});
        sim::World w(open);
        w.step(held({Control::SwitchVehicle}));
        while (w.get<sim::Boat>().speed_mps() < speed && run_ticks < 30 * kOneSecond) {
            w.step(held({Control::Throttle}));
            ++run_ticks;
        }
        run = w.get<sim::Boat>().position().x;
    }
    float a = angle_deg * kPi / 180.0f;
    glm::vec2 dir = -normal * std::sin(a) + glm::vec2(1.0f, 0.0f) * std::cos(a);
    glm::vec2 right(-dir.y, dir.x);
    const float lead_m = 8.0f;
    glm::vec2 start = aim - dir * (run + lead_m) - right * (piling && angle_deg < 75.0f ? 1.0f : 0.0f);
    l.boat_spawn = {{start.x, 0.0f, start.y}, heading_of(dir)};
    glm::vec2 dock = start + right * 8.0f;  // beside the boat, away from where it goes
    l.car_spawn = {{dock.x, 1.0f, dock.y}, 0.0f};
    l.decks.push_back({{dock.x - 2.5f, 0.6f, dock.y - 4.0f}, {dock.x + 2.5f, 1.0f, dock.y + 4.0f}});
    sim::World w(l);
    const sim::Boat& boat = w.get<sim::Boat>();
    w.step(held({Control::SwitchVehicle}));
    if (w.get<sim::Player>().vehicle() != sim::Vehicle::Boat) return "could not board the boat";
    auto where = [&] { return distance({boat.position().x, boat.position().z}); };
    auto aground = [&]() -> std::string {
        glm::vec3 f = boat.pose().forward_flat(), p = boat.position();
        for (float along : {-0.45f, 0.45f}) {
            glm::vec3 end = p + f * (along * boat.params().length_m);
            if (w.terrain().ground_height({end.x, end.z}) > -boat.params().min_depth_m) return "aground";
        }
        for (float along : {-0.3f, 0.0f, 0.3f}) {  // the hull's collision circles
            glm::vec3 c3 = p + f * (along * boat.params().length_m);
            glm::vec2 c(c3.x, c3.z);
            if (w.terrain().resolve_solids(c, 0.5f * boat.params().beam_m - 0.25f, p.y - 0.5f, p.y + 1.8f))
                return "inside a piling";
        }
        return "";
    };
    float closest = where();
    int approach = run_ticks + int(std::ceil((lead_m + 4.0f) / speed * kOneSecond));
    for (int t = 0; t < approach + 2 * kOneSecond; ++t) {
        w.step(t < approach && boat.speed_mps() >= speed ? TickInput{} : held({Control::Throttle}));
        closest = std::min(closest, where());
        if (std::string what = aground(); !what.empty()) return "while sailing in: " + what;
    }
    if (closest > 4.0f) return "never reached it (closest " + std::to_string(closest) + " m)";
    // Head on it backs off; coming at an angle it has swung along and steers away.
    TickInput in = held({Control::Brake});
    if (angle_deg < 75.0f) {
        glm::vec3 f = boat.pose().forward_flat();
        bool left = f.z * normal.x - f.x * normal.y >= 0.0f;
        in = held({Control::Throttle, left ? Control::SteerLeft : Control::SteerRight});
    }
    std::vector<float> d{where()};
    for (int t = 1; t <= 2 * kOneSecond; ++t) {
        w.step(in);
        d.push_back(where());
        if (std::string what = aground(); !what.empty()) return "while getting away: " + what;
        glm::vec3 v = boat.velocity();
        if (std::sqrt(v.x * v.x + v.z * v.z) > 0.5f && t >= 10 && d[size_t(t)] > d[size_t(t - 10)] + 0.05f) return "";
    }
    return "not free two seconds after getting away: speed " + std::to_string(boat.speed_mps()) + " m/s, " +
           std::to_string(where()) + " m from it";
}

TEST(VehicleContact, BoatGetsAwayFromTheQuayAndAPiling) {
    for (bool piling : {false, true})
        for (float angle : {90.0f, 60.0f, 30.0f})
            for (float speed : {3.0f, 8.0f})
                EXPECT_EQ(sail_into(piling, angle, speed), "")
                    << (piling ? "piling" : "quay") << " at " << angle << " degrees, " << speed << " m/s";
}

TEST(VehicleContact, SlidesAlongTheQuayInsteadOfStopping) {
    // A glancing blow keeps most of the speed along the edge.
    auto [run, ticks] = run_up(15.0f);
    glm::vec2 dir(std::cos(20.0f * kPi / 180.0f), std::sin(20.0f * kPi / 180.0f));
    glm::vec2 start = glm::vec2(0.0f) - dir * (run + 6.0f);
    sim::LevelDesc level = open_level();
    level.car_spawn = {{start.x, 1.0f, start.y}, heading_of(dir)};
    sim::World w(level);
    const sim::Car& car = w.get<sim::Car>();
    for (int t = 0; t < ticks + 2 * kOneSecond; ++t) w.step(cruise(car, 15.0f));
    EXPECT_GT(car.speed_mps(), 8.0f);
    EXPECT_LT(car.position().z, 0.0f);
}

TEST(VehicleContact, ClimbsAKerb) {
    for (float angle : {90.0f, 60.0f, 30.0f})
        for (float speed : {5.0f, 15.0f}) {
            sim::LevelDesc l = open_level();
            l.decks.push_back({{-100.0f, 0.8f, -60.0f}, {100.0f, 1.2f, -20.0f}});  // 20 cm up
            auto [run, ticks] = run_up(speed);
            float a = angle * kPi / 180.0f;
            glm::vec2 dir(std::cos(a), std::sin(a));
            glm::vec2 start = glm::vec2(0.0f, -60.0f) - dir * (run + 6.0f);
            l.car_spawn = {{start.x, 1.0f, start.y}, heading_of(dir)};
            sim::World w(l);
            const sim::Car& car = w.get<sim::Car>();
            for (int t = 0; t < ticks + 2 * kOneSecond; ++t) w.step(cruise(car, speed));
            EXPECT_NEAR(car.position().y, 1.2f, 0.02f) << angle << " degrees, " << speed << " m/s";
            EXPECT_GT(car.speed_mps(), 0.8f * speed) << angle << " degrees, " << speed << " m/s";
        }
}

}  // namespace
