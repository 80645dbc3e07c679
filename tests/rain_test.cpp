// sim/rain: drops on the windshield's affinity grid, the wipers' particle model and
// the conversions between them, on a flat test glass and on the harbour car's glass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include <unistd.h>

#include "SimTestLevel.h"
#include "game/level/LevelError.h"
#include "game/level/LevelLoader.h"
#include "ErrorMessage.h"
#include "sim/rain/RainSim.h"
#include "sim/world/World.h"

namespace {

namespace fs = std::filesystem;
using sim::RainSim;
using sim::WiperMode;

constexpr float kDt = 1.0f / 60.0f;
constexpr float kRake = 0.76f;  // about the harbour car's 43 degrees
constexpr float kToMps = 1.0f / 3.6f;

RainSim flat_rain(const sim::RainParams& p = {}, uint64_t seed = 11) {
    std::vector<glm::vec3> lower, upper;
    sim::GlassSurface::flat_edges(1.4f, 0.8f, kRake, lower, upper);
    return RainSim(p, lower, upper, seed);
}

sim::RainForces parked(const RainSim& r) { return r.forces_for(0.0f, glm::vec2(0.0f), {0.0f, -9.81f, 0.0f}); }

double mean_v(const RainSim& r) {
    double sum = 0.0;
    for (const sim::RainDrop& d : r.drops()) sum += d.pos_m.y;
    return r.drops().empty() ? 0.0 : sum / double(r.drops().size());
}

void expect_balanced(const RainSim& r) {
    const sim::RainLedger& l = r.ledger();
    const double expected = l.added_mg - l.evaporated_mg - l.drained_mg;
    EXPECT_NEAR(r.mass_on_glass_mg(), expected, 1e-5 * l.added_mg + 1e-3)
        << "added " << l.added_mg << " evaporated " << l.evaporated_mg << " drained " << l.drained_mg;
}

void expect_one_drop_per_cell(const RainSim& r) {
    std::set<int> cells;
    for (const sim::RainDrop& d : r.drops()) {
        EXPECT_TRUE(cells.insert(d.cell).second) << "two drops in cell " << d.cell;
        EXPECT_EQ(r.glass().cell_of(d.pos_m), d.cell);
        EXPECT_GT(d.mass_mg, 0.0f);
    }
}

// Blades whose whole sweep stays on the glass, so that no water is pushed off it.
sim::RainParams blades_inside() {
    sim::RainParams p;
    p.blades[0] = {{0.5f, 0.05f}, 0.1f, 0.7f, 0.4f, 2.3f};
    p.blades[1] = {{0.5f, 0.45f}, 0.05f, 0.4f, 0.4f, 2.3f};
    return p;
}

TEST(Rain, MassIsConservedAcrossMergesAndGridParticleConversions) {
    sim::RainParams p = blades_inside();
    p.new_drop_max_mg = 80.0f;
    p.slide_mass_mg = 40.0f;  // most drops run: cell steps, merges on the way, trails
    RainSim r = flat_rain(p);
    size_t most_particles = 0, most_moving = 0, most_trails = 0;
    for (int t = 0; t < 360; ++t) {
        r.advance(t < 240 ? 1.0f : 0.0f, WiperMode::High, 0.0f, parked(r), kDt);
        most_particles = std::max(most_particles, r.particles().size());
        size_t moving = 0, trails = 0;
        for (const sim::RainDrop& d : r.drops()) {
            moving += d.vel_mps != glm::vec2(0.0f);
            trails += d.trail();
        }
        most_moving = std::max(most_moving, moving);
        most_trails = std::max(most_trails, trails);
        expect_balanced(r);
        if (::testing::Test::HasFailure()) FAIL() << "tick " << t;
    }
    expect_one_drop_per_cell(r);
    EXPECT_GT(r.ledger().added_mg, 1000.0);
    EXPECT_GT(most_moving, 50u);                // the grid model did move drops...
    EXPECT_GT(most_trails, 10u);                // ...that left trailing drops...
    EXPECT_GT(most_particles, 100u);            // ...and the blades did convert them
    EXPECT_GT(r.ledger().evaporated_mg, 0.0);   // trailing drops and film
    EXPECT_GT(r.ledger().drained_mg, 0.0);      // run off the lower edge, and counted
}

TEST(Rain, RainOnAStillGlassMergesWhereItLandsOnADrop) {
    sim::RainParams p;
    p.slide_mass_mg = 5000.0f;  // nothing moves: drops only merge where rain lands on them
    RainSim r = flat_rain(p);
    for (int t = 0; t < 600; ++t) r.advance(3.0f, WiperMode::Off, 0.0f, parked(r), kDt);
    expect_balanced(r);
    expect_one_drop_per_cell(r);
    // n drops landing uniformly on C cells leave C (1 - e^(-n/C)) of them wet, one drop
    // each; n from the mass that fell (masses uniform, so to well under 1%).
    const double landed = r.ledger().added_mg / (0.5 * double(p.new_drop_min_mg + p.new_drop_max_mg));
    const double cells = double(r.glass().cell_count());
    const double expected = cells * (1.0 - std::exp(-landed / cells));
    ASSERT_GT(landed, 0.3 * cells);  // enough rain that a good share lands on drops
    EXPECT_NEAR(double(r.drops().size()), expected, 0.03 * expected) << "of about " << landed << " drops landed";
}

TEST(Rain, DropsRunDownTheGlassWhenParkedAndUpAt100Kmh) {
    auto seeded = [] {
        RainSim r = flat_rain();
        sim::Rng rng(5, 9);
        for (int k = 0; k < 400; ++k)
            r.add_drop({rng.range(0.05f, 1.3f), rng.range(0.3f, 0.5f)}, r.params().slide_mass_mg * rng.range(1.2f, 3.0f));
        return r;
    };
    RainSim still = seeded(), fast = seeded();
    const double v0 = mean_v(still);
    for (int t = 0; t < 30; ++t) {
        still.advance(0.0f, WiperMode::Off, 0.0f, parked(still), kDt);
        const float speed = 100.0f * kToMps;
        fast.advance(0.0f, WiperMode::Off, speed, fast.forces_for(speed, glm::vec2(0.0f), {0.0f, -9.81f, 0.0f}), kDt);
    }
    EXPECT_LT(mean_v(still), v0 - 0.01) << "parked: the heavier drops should run down";
    EXPECT_GT(mean_v(fast), v0 + 0.01) << "at 100 km/h the air should push drops up the glass";
    EXPECT_EQ(still.ledger().drained_mg, 0.0);
    EXPECT_EQ(fast.ledger().drained_mg, 0.0);
    expect_balanced(still);
    expect_balanced(fast);
}

TEST(Rain, BrakingSendsDropsDownAndAccelerationUp) {
    auto run = [](float accel) {
        RainSim r = flat_rain();
        sim::Rng rng(6, 9);
        for (int k = 0; k < 300; ++k)
            r.add_drop({rng.range(0.05f, 1.3f), rng.range(0.3f, 0.5f)}, r.params().slide_mass_mg * rng.range(1.0f, 1.5f));
        for (int t = 0; t < 20; ++t) r.advance(0.0f, WiperMode::Off, 10.0f, r.forces_for(10.0f, {accel, 0.0f}, {0.0f, -9.81f, 0.0f}), kDt);
        return mean_v(r);
    };
    EXPECT_LT(run(-8.0f), run(0.0f) - 0.005);
    EXPECT_GT(run(8.0f), run(0.0f) + 0.005);
}

// Water in the inner part of each blade's swept sector (the bead piles up at its ends).
double swept_mass(const RainSim& r) {
    double m = 0.0;
    auto inside = [&](glm::vec2 p) {
        for (const sim::WiperBlade& b : r.blades()) {
            const sim::WiperBladeParams& bp = b.params();
            glm::vec2 rel = p - bp.pivot_m;
            float rho = std::sqrt(rel.x * rel.x + rel.y * rel.y), a = std::atan2(rel.y, rel.x);
            float lo = std::min(bp.rest_rad, bp.rest_rad + bp.sweep_rad), hi = std::max(bp.rest_rad, bp.rest_rad + bp.sweep_rad);
            if (rho > bp.inner_m + 0.03f && rho < bp.outer_m - 0.03f && a > lo + 0.2f && a < hi - 0.2f) return true;
        }
        return false;
    };
    for (const sim::RainDrop& d : r.drops())
        if (inside(d.pos_m)) m += d.mass_mg;
    for (const sim::WaterParticle& q : r.particles())
        if (inside(q.pos_m)) m += q.mass_mg;
    return m;
}

TEST(Rain, WipersOnHighWithoutRainLeaveTheSweptAreaNearlyDry) {
    RainSim r = flat_rain();
    for (int t = 0; t < 180; ++t) r.advance(1.0f, WiperMode::Off, 0.0f, parked(r), kDt);
    const double wet = swept_mass(r);
    ASSERT_GT(wet, 500.0);
    for (int t = 0; t < 240; ++t) r.advance(0.0f, WiperMode::High, 0.0f, parked(r), kDt);  // four sweeps and more
    int settle = 0;
    while (!r.motor().parked() && settle++ < 120) r.advance(0.0f, WiperMode::Off, 0.0f, parked(r), kDt);
    ASSERT_TRUE(r.motor().parked());
    const double left = swept_mass(r);
    EXPECT_LT(left, 0.03 * wet) << "before " << wet << " mg, after " << left << " mg";
    expect_balanced(r);
    EXPECT_GT(r.ledger().drained_mg, 0.0);  // the blades push water off the glass's lower edge
}

TEST(Rain, AWiperReversalLosesOrDuplicatesNoDrop) {
    sim::RainParams p = blades_inside();
    p.slide_mass_mg = 5000.0f;
    p.film_fraction = 0.0f;  // no film: every milligram goes grid -> particles -> grid
    RainSim r = flat_rain(p);
    sim::Rng rng(8, 3);
    for (int k = 0; k < 2500; ++k) r.add_drop({rng.range(0.0f, 1.39f), rng.range(0.0f, 0.79f)}, rng.range(4.0f, 40.0f));
    const double total = r.mass_on_glass_mg();
    float max_before = 0.0f;
    for (const sim::RainDrop& d : r.drops()) max_before = std::max(max_before, d.mass_mg);
    // Low speed: out to the far end, reverse, back to rest and stop.
    bool reversed = false;
    float last = 0.0f;
    for (int t = 0; t < int(p.motor.low_cycle_s * 60.0f) + 200; ++t) {
        r.advance(0.0f, t < 10 ? WiperMode::Low : WiperMode::Off, 0.0f, parked(r), kDt);
        reversed = reversed || r.motor().fraction() < last;
        last = r.motor().fraction();
        EXPECT_NEAR(r.mass_on_glass_mg(), total, 1e-5 * total) << "tick " << t;
    }
    ASSERT_TRUE(reversed);
    EXPECT_EQ(r.ledger().drained_mg, 0.0);
    EXPECT_EQ(r.ledger().evaporated_mg, 0.0);
    expect_one_drop_per_cell(r);
    // Deferred conversion: the bead left at the reversal does not pour into one giant drop.
    float max_after = 0.0;
    for (const sim::RainDrop& d : r.drops()) max_after = std::max(max_after, d.mass_mg);
    EXPECT_LT(max_after, 3.0f * p.defer_mass_mg);
}

TEST(Rain, TheBeadGrowsAlongTheBladeAndSpillsAtTheEndOfTheSweep) {
    sim::RainParams p;
    p.blades[0] = {{0.5f, 0.1f}, 0.1f, 0.6f, 0.3f, 2.5f};      // all its sweep on the glass
    p.blades[1] = {{0.02f, 0.98f}, 0.0f, 0.01f, 0.0f, 0.1f};   // a short blade parked in a corner, out of the way
    p.slide_mass_mg = 5000.0f;
    p.film_fraction = 0.0f;
    RainSim r = flat_rain(p);
    sim::Rng rng(9, 4);
    for (int k = 0; k < 4000; ++k) r.add_drop({rng.range(0.0f, 1.39f), rng.range(0.0f, 0.79f)}, rng.range(4.0f, 40.0f));
    const double total = r.mass_on_glass_mg();
    const sim::WiperBladeParams& bp = r.blades()[0].params();
    const float end = bp.rest_rad + bp.sweep_rad;
    // Water along the rubber (between its ends) at angles from the pivot in [lo, hi].
    auto mass_in = [&](float lo, float hi) {
        double m = 0.0;
        auto add = [&](glm::vec2 pos, float mass) {
            const glm::vec2 rel = pos - bp.pivot_m;
            const float rho = std::sqrt(rel.x * rel.x + rel.y * rel.y), a = std::atan2(rel.y, rel.x);
            if (rho >= bp.inner_m && rho <= bp.outer_m && a >= lo && a <= hi) m += mass;
        };
        for (const sim::RainDrop& d : r.drops()) add(d.pos_m, d.mass_mg);
        for (const sim::WaterParticle& q : r.particles()) add(q.pos_m, q.mass_mg);
        return m;
    };
    auto bead = [&] {
        double m = 0.0;
        for (const sim::WaterParticle& q : r.particles()) m += q.mass_mg;
        return m;
    };
    const double swept_before = mass_in(bp.rest_rad + 0.3f, end - 0.3f);
    const double end_before = mass_in(end - 0.1f, end + 0.3f);
    ASSERT_GT(swept_before, 10000.0);
    // Out on low: the bead grows as the blade gathers the water in its way.
    double bead_quarter = 0.0;
    int t = 0;
    for (; r.motor().fraction() < 0.97f && t < 300; ++t) {
        r.advance(0.0f, WiperMode::Low, 0.0f, parked(r), kDt);
        if (bead_quarter == 0.0 && r.motor().fraction() >= 0.25f) bead_quarter = bead();
    }
    ASSERT_LT(t, 300) << "the blade should reach the end of its sweep";
    EXPECT_GT(bead(), 2.0 * bead_quarter) << "at a quarter of the sweep " << bead_quarter << " mg";
    // Switched off, the blade reverses and parks: the bead stays where the sweep ended
    // (drops again, or particles while big drops are near) and is not dragged back.
    for (int k = 0; k < 300 && !r.motor().parked(); ++k) r.advance(0.0f, WiperMode::Off, 0.0f, parked(r), kDt);
    for (int k = 0; k < 10; ++k) r.advance(0.0f, WiperMode::Off, 0.0f, parked(r), kDt);
    ASSERT_TRUE(r.motor().parked());
    const double end_after = mass_in(end - 0.1f, end + 0.3f), swept_after = mass_in(bp.rest_rad + 0.3f, end - 0.3f);
    EXPECT_GT(end_after - end_before, 0.7 * swept_before) << "before " << end_before << " mg, after " << end_after << " mg";
    EXPECT_LT(swept_after, 0.03 * swept_before);
    EXPECT_NEAR(r.mass_on_glass_mg(), total, 1e-5 * total);
}

TEST(Rain, InvalidParametersAreRefusedNamingThem) {
    sim::RainParams p;
    p.cell_size_m = 0.0f;
    EXPECT_NE(message_of([&] { flat_rain(p); }).find("cell_size_m"), std::string::npos);
    p = {};
    p.particle_mass_mg = -1.0f;
    EXPECT_NE(message_of([&] { flat_rain(p); }).find("particle_mass_mg"), std::string::npos);
    RainSim r = flat_rain();
    EXPECT_NE(message_of([&] { r.advance(-0.5f, WiperMode::Off, 0.0f, parked(r), kDt); }).find("intensity"), std::string::npos);
    std::vector<glm::vec3> one = {{0, 0, 0}};
    EXPECT_NE(message_of([&] { RainSim(sim::RainParams{}, one, one, 1); }).find("two points"), std::string::npos);
}

TEST(Rain, SameSeedSameHashAndTheWorldHashesIt) {
    sim::LevelDesc level = make_test_level();
    sim::GlassSurface::flat_edges(1.4f, 0.8f, kRake, level.rain.glass_lower, level.rain.glass_upper);
    level.rain_intensity = 1.0f;
    auto run = [&](int threads) {
        sim::World w(level, sim::WorldOptions{threads});
        for (int t = 0; t < 240; ++t) {
            sim::TickInput in;
            in.set(sim::Control::Throttle, t > 60);
            in.set(sim::Control::Wipers, t == 30 || t == 32);  // pressed twice: low
            w.step(in);
        }
        EXPECT_GT(w.get<RainSim>().drops().size(), 50u);
        return w.hash();
    };
    sim::WorldHash a = run(1), b = run(2);
    EXPECT_EQ(a.world, b.world);
    sim::World w(level);
    auto names = w.subsystem_names();
    EXPECT_NE(std::find(names.begin(), names.end(), "rain"), names.end());
}

TEST(Rain, TheRainStateChangesTheWorldHash) {
    sim::LevelDesc level = make_test_level();
    sim::GlassSurface::flat_edges(1.4f, 0.8f, kRake, level.rain.glass_lower, level.rain.glass_upper);
    level.rain_intensity = 1.0f;
    sim::World a(level), b(level);
    for (int t = 0; t < 60; ++t) {
        a.step({});
        b.step({});
    }
    ASSERT_EQ(a.hash(), b.hash());
    b.get<RainSim>().add_drop({0.7f, 0.4f}, 30.0f);  // one more drop, nothing else differs
    const sim::WorldHash ha = a.hash(), hb = b.hash();
    EXPECT_NE(ha.world, hb.world);
    const std::vector<std::string> names = a.subsystem_names();
    ASSERT_EQ(ha.parts.size(), names.size());
    for (size_t k = 0; k < names.size(); ++k)
        EXPECT_EQ(ha.parts[k] != hb.parts[k], names[k] == "rain") << names[k];
    // And it stays different as both go on.
    a.step({});
    b.step({});
    EXPECT_NE(a.hash().world, b.hash().world);
}

// A copy of the harbour level with one replacement in its JSON, assets linked.
fs::path harbour_variant(const fs::path& dir, const std::string& from, const std::string& to) {
    const fs::path data = fs::path(SPINDRIFT_TEST_DATA).parent_path().parent_path() / "levels";
    std::ifstream in(data / "harbour.json");
    std::stringstream text;
    text << in.rdbuf();
    std::string json = text.str();
    auto at = json.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) json.replace(at, from.size(), to);
    fs::create_directories(dir);
    if (!fs::exists(dir / "rainy")) fs::create_directory_symlink(data / "harbour", dir / "rainy");
    std::ofstream(dir / "rainy.json") << json;
    return dir / "rainy.json";
}

TEST(RainLevel, TheHarbourCarsCurvedWindshieldIsTheGlass) {
    game::LoadedLevel level = game::load_level("harbour");
    const sim::RainDesc& rain = level.sim.rain;
    ASSERT_GE(rain.glass_lower.size(), 3u);
    ASSERT_EQ(rain.glass_lower.size(), rain.glass_upper.size());
    // Bowed forward in the middle, rising backwards.
    const size_t mid = rain.glass_lower.size() / 2;
    EXPECT_GT(rain.glass_lower[mid].x, rain.glass_lower.front().x + 0.01f);
    EXPECT_LT(rain.glass_upper[mid].x, rain.glass_lower[mid].x);
    EXPECT_GT(rain.glass_upper[mid].y, rain.glass_lower[mid].y + 0.3f);
    sim::Rng rng(1, 1);
    sim::GlassSurface glass(rain.glass_lower, rain.glass_upper, rain.cell_size_m, rng);
    EXPECT_NEAR(glass.width_m(), 1.49f, 0.05f);
    EXPECT_NEAR(glass.height_m(), 0.89f, 0.05f);
    // Curved: the across tangent turns from one side to the other.
    const sim::GlassCell& left = glass.cell(glass.cell_of({0.05f, 0.4f}));
    const sim::GlassCell& right = glass.cell(glass.cell_of({glass.width_m() - 0.05f, 0.4f}));
    EXPECT_GT(left.tangent_u.x, 0.02f);
    EXPECT_LT(right.tangent_u.x, -0.02f);
}

TEST(RainLevel, NegativeIntensityAndZeroCellSizeAreRefusedNamingTheField) {
    const fs::path dir = fs::temp_directory_path() / ("spindrift_rain_" + std::to_string(::getpid()));
    auto refused = [&](const std::string& from, const std::string& to, const std::string& field) {
        fs::path json = harbour_variant(dir, from, to);
        std::string msg = message_of([&] { game::load_level(json.string()); });
        EXPECT_NE(msg.find(field), std::string::npos) << msg;
    };
    refused("\"intensity\": 0.0", "\"intensity\": -0.5", "rain.intensity");
    refused("\"cell_size_m\": 0.008", "\"cell_size_m\": 0", "rain.cell_size_m");
    fs::remove_all(dir);
}

}  // namespace
