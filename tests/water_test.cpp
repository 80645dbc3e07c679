// sim/water: the wave grid's physics, the seed's splash rules, spray, and the coupling
// to thrown objects, the boat and rain in a small world built in code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "ErrorMessage.h"
#include "SimTestLevel.h"
#include "sim/objects/ThrownObjects.h"
#include "sim/player/Player.h"
#include "sim/vehicle/Boat.h"
#include "sim/water/WaterSim.h"
#include "sim/world/World.h"

namespace {

using sim::Control;
using sim::TickInput;

constexpr float kDt = 1.0f / 60.0f;

TEST(SplashSheet, FirstSplashFollowsTheSeedsRing) {
    sim::SplashSheetParams p;
    sim::WaveGrid flat({}, kDt);
    sim::Rng rng(3);
    for (int rim : {1, 2}) {
        sim::SplashSheet s(p);
        s.reset({10.0f, 20.0f}, flat, 0.0f);
        const float radius = float(rim) * p.spacing_m;  // diameter 2d, then 4d
        const float momentum = 1000.0f;
        const float top = s.launch_speed(momentum);
        EXPECT_NEAR(top, momentum * p.speed_per_momentum, 1e-4f);
        const sim::SplashSheet::Band band = s.ring_band(radius);
        ASSERT_EQ(band.inner, rim);
        ASSERT_EQ(band.outer, rim + p.min_skirt_rings);
        // 8 vertices per ring of Chebyshev radius r: the seed's ring (8 at 2d, 16 at
        // 4d) and the skirt rings outside it.
        int expected = 0;
        for (int r = band.inner; r <= band.outer; ++r) expected += 8 * r;
        EXPECT_EQ(s.first_splash(radius, momentum, rng, flat, 0.0f), expected);
        EXPECT_TRUE(s.active());
        const int half = s.size() / 2;
        for (int j = 0; j < s.size(); ++j)
            for (int i = 0; i < s.size(); ++i) {
                size_t idx = size_t(j) * size_t(s.size()) + size_t(i);
                int di = i - half, dj = j - half;
                int ring = std::max(std::abs(di), std::abs(dj));
                bool in_band = ring >= band.inner && ring <= band.outer;
                ASSERT_EQ(s.airborne()[idx], in_band ? 1 : 0) << di << "," << dj;
                if (!in_band) continue;
                glm::vec3 v = s.velocities()[idx];
                if (ring == rim) {  // the seed's speeds on its ring
                    EXPECT_GE(v.y, 0.1f * top - 1e-5f);
                    EXPECT_LE(v.y, top);
                } else {  // the skirt flies slower than the rim
                    EXPECT_LT(v.y, top * (1.0f - 0.5f / float(p.min_skirt_rings + 1)));
                }
                const float l1 = float(std::abs(di) + std::abs(dj));
                if (dj == 0) {  // along an axis: all of it outward
                    EXPECT_FLOAT_EQ(v.x, float(di > 0 ? 1 : -1) * v.y);
                    EXPECT_EQ(v.z, 0.0f);
                } else if (std::abs(di) == std::abs(dj)) {  // diagonal: half on each axis
                    EXPECT_FLOAT_EQ(v.x, float(di > 0 ? 1 : -1) * 0.5f * v.y);
                    EXPECT_FLOAT_EQ(v.z, float(dj > 0 ? 1 : -1) * 0.5f * v.y);
                } else {  // between: the two blended, pointing away from the centre
                    EXPECT_NEAR(v.x, float(di) / l1 * v.y, 1e-5f);
                    EXPECT_NEAR(v.z, float(dj) / l1 * v.y, 1e-5f);
                }
                EXPECT_NEAR(s.positions()[idx].x, 10.0f + float(di) * p.spacing_m, 1e-4f);
            }
    }
    // A stone of 0.22 m radius: its rim ring and a skirt as wide, within the sheet.
    sim::SplashSheet s(p);
    sim::SplashSheet::Band b = s.ring_band(0.22f);
    EXPECT_EQ(b.inner, 6);
    EXPECT_EQ(b.outer, 12);
    EXPECT_LE(b.outer, (s.size() - 1) / 2);
    EXPECT_LT(s.launch_speed(1e9f), p.max_speed_mps + 1e-4f);
}

TEST(SplashSheet, BowSplashLeavesTheVerticesBehindAlone) {
    sim::SplashSheet s({});
    sim::WaveGrid flat({}, kDt);
    sim::Rng rng(5);
    s.reset({0.0f, 50.0f}, flat, 0.0f);
    const glm::vec2 ahead = glm::normalize(glm::vec2(1.0f, 0.5f));
    int n = s.first_splash(0.6f, 1500.0f, rng, flat, 0.0f, ahead);
    EXPECT_GT(n, 40);
    int half = s.size() / 2;
    for (int j = 0; j < s.size(); ++j)
        for (int i = 0; i < s.size(); ++i)
            if (s.airborne()[size_t(j) * size_t(s.size()) + size_t(i)]) {
                EXPECT_GE(float(i - half) * ahead.x + float(j - half) * ahead.y, 0.0f);
            }
    // Only hidden vertices are launched again: a second call right away adds nothing.
    EXPECT_EQ(s.first_splash(0.6f, 1500.0f, rng, flat, 0.0f, ahead), 0);
}

TEST(SplashSheet, VerticesFallBackBelowTheSurfaceAndRipple) {
    sim::SplashSheet s({});
    sim::WaveGrid flat({}, kDt);
    sim::Rng rng(9);
    s.reset({5.0f, 30.0f}, flat, 0.0f);
    int launched = s.first_splash(0.22f, 1400.0f, rng, flat, 0.0f);
    launched += s.second_splash(0.22f, 1400.0f, rng, flat, 0.0f);
    std::vector<sim::Ripple> ripples;
    float highest = 0.0f;
    int ticks = 0, torn = 0;
    while (s.active() && ticks < 600) {
        s.step(kDt, flat, 0.0f, ripples);
        for (const glm::vec3& p : s.positions()) highest = std::max(highest, p.y);
        // What tore off had flown clear of the film: up in the air and moving.
        for (const sim::TornOff& t : s.torn()) {
            EXPECT_GT(t.position.y, -s.params().hidden_depth_m);
            EXPECT_GT(glm::length(t.velocity), 0.0f);
        }
        EXPECT_LE(int(s.torn().size()), s.tore_off());  // one in torn_drop_share flies on as a drop
        torn += s.tore_off();
        ++ticks;
    }
    EXPECT_LT(ticks, 120);  // back within two seconds
    EXPECT_GT(highest, 0.3f);  // but it really rose
    // Every launched vertex either fell back (a ripple) or tore off as a droplet: the
    // crown's rim and the jet's top break into drops, but a good part of the film
    // comes down whole.
    EXPECT_EQ(int(ripples.size()) + torn, launched);
    EXPECT_GT(torn, launched / 10) << torn << " of " << launched << " tore off";
    EXPECT_LT(torn, launched * 3 / 4) << torn << " of " << launched << " tore off";
    for (const glm::vec3& p : s.positions()) ASSERT_NEAR(p.y, -s.params().hidden_depth_m, 1e-6f);
    for (uint8_t a : s.airborne()) ASSERT_EQ(a, 0);
}

TEST(SprayParticles, FlyOutwardAndUpThenLandWithARipple) {
    sim::SprayParams p;
    p.max_particles = 500;
    sim::SprayParticles spray(p);
    sim::WaveGrid flat({}, kDt);
    sim::Rng rng(11);
    const glm::vec3 centre(10.0f, 0.0f, 40.0f);
    EXPECT_EQ(spray.emit_splash(centre, 0.3f, {6.0f, -9.0f, 2.0f}, 300, rng), 300);
    for (const sim::SprayParticle& q : spray.particles()) {
        glm::vec2 out(q.position.x - centre.x, q.position.z - centre.z);
        EXPECT_NEAR(glm::length(out), 0.3f, 1e-4f);
        EXPECT_GT(q.velocity.x * out.x + q.velocity.z * out.y, 0.0f);
        EXPECT_GE(q.velocity.y, 0.5f * 0.25f * 17.0f - 1e-4f);
    }
    EXPECT_EQ(spray.emit_splash(centre, 0.3f, {6.0f, -9.0f, 2.0f}, 300, rng), 200);  // up to the cap
    std::vector<sim::Ripple> ripples;
    sim::JobPool pool(2);
    for (int t = 0; t < 300 && !spray.particles().empty(); ++t) spray.step(kDt, flat, 0.0f, ripples, &pool);
    EXPECT_TRUE(spray.particles().empty());
    EXPECT_EQ(ripples.size(), 500u);
    EXPECT_THROW(sim::SprayParticles(sim::SprayParams{.max_particles = size_t(1) << 40}), std::invalid_argument);
}

// A world from the code-built test level with a wave grid of the test's own as the sea.
struct Harbour {
    sim::World world;
    sim::WaterSim* water = nullptr;
    explicit Harbour(sim::LevelDesc level, int threads = 1, sim::WaterParams params = {})
        : world(std::move(level), sim::standard_subsystems_with_water(params), {threads}),
          water(&world.get<sim::WaterSim>()) {}
};

// Dropped (no throw speed) from 4 m above the sea, away from the pier.
constexpr sim::ThrowKind kDroppedStone{0.22f, 2600.0f, 0.0f};
constexpr sim::ThrowKind kDroppedFloat{0.30f, 240.0f, 0.0f};

void drop(Harbour& h, const sim::ThrowKind& kind, glm::vec3 at) {
    h.world.get<sim::ThrownObjects>().launch(kind, at, {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f});
}

TEST(Water, HeavyObjectSplashesTwiceInOrderAndSinksToTheBottom) {
    Harbour h(make_test_level());
    drop(h, kDroppedStone, {50.0f, 4.0f, 20.0f});
    int first = -1, second = -1, firsts = 0, seconds = 0;
    float dip = 0.0f, refill = 0.0f, highest = 0.0f;
    size_t spray = 0;
    for (int t = 0; t < 600; ++t) {
        h.world.step({});
        for (const sim::SplashEvent& e : h.water->splashes()) {
            if (e.kind == sim::SplashEvent::Kind::First) {
                first = t;
                ++firsts;
                dip = h.water->grid().sample({e.position.x, e.position.z});
            } else {
                second = t;
                ++seconds;
                refill = h.water->grid().sample({e.position.x, e.position.z});
            }
        }
        for (const sim::SplashSheet& s : h.water->sheets())
            for (size_t k = 0; k < s.positions().size(); ++k)
                if (s.airborne()[k]) highest = std::max(highest, s.positions()[k].y);
        spray = std::max(spray, h.water->spray().particles().size());
    }
    ASSERT_EQ(firsts, 1);
    ASSERT_EQ(seconds, 1);
    EXPECT_GT(second, first);
    EXPECT_GE(second - first, 15);  // the crater refills in 0.25..0.4 s
    EXPECT_LE(second - first, 24);
    EXPECT_LT(dip, -0.02f);  // the surface dipped where it went in
    // The jet came because the crater refilled, not because the wait ran out.
    EXPECT_GE(refill, 0.25f * dip) << "dip " << dip << " m, centre " << refill << " m at the jet";
    EXPECT_GT(highest, 0.2f);
    EXPECT_LT(highest, 3.0f);  // metres, not kilometres
    const sim::ThrownObject& stone = h.world.get<sim::ThrownObjects>().objects().at(0);
    EXPECT_NEAR(stone.position.y, -6.0f + stone.radius_m, 0.02f);
    EXPECT_GT(spray, 100u);  // a stone of ~110 kg at ~9 m/s: 0.2 droplets per kg m/s
}

struct SplashSize {
    float ring_m = 0.0f;   // mean distance of the launched sheet vertices from the entry
    float crown_m = 0.0f;  // highest sheet vertex
    size_t spray = 0;      // most droplets in the air at once
};

SplashSize splash_of(const sim::ThrowKind& kind, glm::vec3 velocity) {
    Harbour h(make_test_level());
    h.world.get<sim::ThrownObjects>().launch(kind, {50.0f, 1.0f, 20.0f}, {0.0f, 0.0f, 1.0f}, velocity);
    SplashSize out;
    for (int t = 0; t < 240; ++t) {
        h.world.step({});
        for (const sim::SplashEvent& e : h.water->splashes()) {
            if (e.kind != sim::SplashEvent::Kind::First) continue;
            const sim::SplashSheet& sheet = h.water->sheets()[size_t(e.sheet)];
            double sum = 0.0;
            int n = 0;
            for (size_t k = 0; k < sheet.positions().size(); ++k)
                if (sheet.airborne()[k]) {
                    sum += glm::length(glm::vec2(sheet.positions()[k].x - e.position.x, sheet.positions()[k].z - e.position.z));
                    ++n;
                }
            out.ring_m = n ? float(sum / n) : 0.0f;
        }
        for (const sim::SplashSheet& sheet : h.water->sheets())
            for (size_t k = 0; k < sheet.positions().size(); ++k)
                if (sheet.airborne()[k]) out.crown_m = std::max(out.crown_m, sheet.positions()[k].y);
        out.spray = std::max(out.spray, h.water->spray().particles().size());
    }
    return out;
}

TEST(Water, BiggerOrFasterStoneMakesABiggerSplash) {
    const glm::vec3 slow(0.0f, -5.0f, 0.0f), fast(0.0f, -10.0f, 0.0f);
    constexpr sim::ThrowKind kBigStone{0.44f, 2600.0f, 0.0f};
    const SplashSize base = splash_of(kDroppedStone, slow);
    const SplashSize big = splash_of(kBigStone, slow);
    const SplashSize quick = splash_of(kDroppedStone, fast);
    ASSERT_GT(base.ring_m, 0.0f);
    EXPECT_GT(big.ring_m, 1.5f * base.ring_m);  // the ring follows the diameter
    EXPECT_GT(big.crown_m, base.crown_m);
    EXPECT_GT(big.spray, base.spray);
    EXPECT_NEAR(quick.ring_m, base.ring_m, 0.15f * base.ring_m);  // speed does not widen it
    EXPECT_GT(quick.crown_m, base.crown_m);
    EXPECT_GT(quick.spray, base.spray);
}

TEST(Water, DropletsRippleTheGridWhereTheyLand) {
    // Two harbours with the same stone, one without spray: the sheets draw the same
    // random numbers, so the grids differ only by the droplets' ripples.
    sim::WaterParams dry;
    dry.max_spray_per_impact = 0;
    dry.spray.max_particles = 0;  // nor the droplets torn off the sheets
    Harbour with(make_test_level()), without(make_test_level(), 1, dry);
    drop(with, kDroppedStone, {50.0f, 4.0f, 20.0f});
    drop(without, kDroppedStone, {50.0f, 4.0f, 20.0f});
    std::vector<glm::vec3> before;
    int landing_ticks = 0;
    for (int t = 0; t < 300 && landing_ticks < 5; ++t) {
        before.clear();
        for (const sim::SprayParticle& q : with.water->spray().particles()) before.push_back(q.position);
        with.world.step({});
        without.world.step({});
        const auto& a = with.water->grid().heights();
        const auto& b = without.water->grid().heights();
        const sim::WaveGrid& g = with.water->grid();
        // Torn film joins the spray as it flies: landed means fewer than were there plus those.
        size_t joined = 0;
        for (const sim::SplashSheet& sheet : with.water->sheets()) joined += sheet.torn().size();
        const bool landed = with.water->spray().particles().size() < before.size() + joined;
        if (!landed && landing_ticks == 0) {
            ASSERT_EQ(a, b) << "tick " << t << ": the grids differ before any droplet landed";
            continue;
        }
        if (landing_ticks++ > 0) continue;
        // The first landings: every changed cell lies within a ripple's reach of a
        // droplet that was in the air a tick ago.
        int changed = 0;
        for (int j = 0; j < g.size(); ++j)
            for (int i = 0; i < g.size(); ++i) {
                size_t k = size_t(j) * size_t(g.size()) + size_t(i);
                if (a[k] == b[k]) continue;
                ++changed;
                glm::vec2 cell = g.origin() + glm::vec2(float(i), float(j)) * g.spacing();
                float nearest = 1e9f;
                for (const glm::vec3& q : before) nearest = std::min(nearest, glm::length(glm::vec2(q.x, q.z) - cell));
                ASSERT_LT(nearest, g.spacing() + 0.3f) << "cell " << i << "," << j;
            }
        EXPECT_GT(changed, 0);
    }
    EXPECT_GT(landing_ticks, 0) << "no droplet came down";
}

TEST(Water, LightObjectSplashesOnceFloatsAndRidesTheWaves) {
    Harbour h(make_test_level());
    drop(h, kDroppedFloat, {50.0f, 4.0f, 20.0f});
    int firsts = 0, seconds = 0;
    auto run = [&](int ticks) {
        for (int t = 0; t < ticks; ++t) {
            h.world.step({});
            for (const sim::SplashEvent& e : h.water->splashes())
                (e.kind == sim::SplashEvent::Kind::First ? firsts : seconds)++;
        }
    };
    run(480);
    EXPECT_EQ(firsts, 1);
    EXPECT_EQ(seconds, 0);
    const sim::ThrownObject& f = h.world.get<sim::ThrownObjects>().objects().at(0);
    const float rest = f.position.y - h.water->height_at({f.position.x, f.position.z});
    EXPECT_GT(rest, 0.0f);  // floating: centre above the surface, less than its radius
    EXPECT_LT(rest, f.radius_m);
    // A long wave (a surge pushed 6 m away) passes under it: it rises and falls with
    // the surface, keeping its draught.
    h.water->disturb({f.position.x + 6.0f, f.position.z}, 5.0f, 0.4f);
    float lo = 1e9f, hi = -1e9f, worst = 0.0f;
    for (int t = 0; t < 300; ++t) {
        run(1);
        const sim::ThrownObject& g = h.world.get<sim::ThrownObjects>().objects().at(0);
        float water = h.water->height_at({g.position.x, g.position.z});
        lo = std::min(lo, water);
        hi = std::max(hi, water);
        worst = std::max(worst, std::fabs(g.position.y - water - rest));
    }
    EXPECT_GT(hi - lo, 0.03f) << "not much of a wave";
    EXPECT_LT(worst, 0.3f * (hi - lo)) << "the float does not follow the surface";
    EXPECT_EQ(firsts, 1);
    EXPECT_EQ(seconds, 0);
}

TEST(Water, LightObjectDriftsWithAPassingWave) {
    Harbour h(make_test_level());
    drop(h, kDroppedFloat, {50.0f, 4.0f, 20.0f});
    for (int t = 0; t < 480; ++t) h.world.step({});
    const glm::vec3 start = h.world.get<sim::ThrownObjects>().objects().at(0).position;
    // Still water: it stays put.
    for (int t = 0; t < 120; ++t) h.world.step({});
    glm::vec3 p = h.world.get<sim::ThrownObjects>().objects().at(0).position;
    EXPECT_LT(glm::length(glm::vec2(p.x - start.x, p.z - start.z)), 0.01f);
    // A long ridge raised 5 m to the -x side sends a straight crest along +x under it.
    // The water under a shallow-water crest moves with it at u = g eta / v: the float
    // goes with it, by less than (g / v) times the integral of eta over time (some of
    // that is the still, raised level the damped crest leaves behind).
    for (float z = start.z - 20.0f; z <= start.z + 20.0f; z += 1.0f)
        h.water->disturb({start.x - 5.0f, z}, 2.0f, -0.1f);
    float peak = -1e9f;
    double eta_dt = 0.0;
    for (int t = 0; t < 360; ++t) {
        h.world.step({});
        p = h.world.get<sim::ThrownObjects>().objects().at(0).position;
        const float eta = h.water->height_at({p.x, p.z});
        peak = std::max(peak, eta);
        eta_dt += eta * kDt;
    }
    const float theory = float(9.81 / h.water->params().grid.wave_speed_mps * eta_dt);
    EXPECT_GT(peak, 0.05f) << "no crest passed";
    EXPECT_GT(theory, 0.05f);
    EXPECT_GT(p.x - start.x, 0.1f) << "the float did not drift with the wave";
    EXPECT_LT(p.x - start.x, theory);
    EXPECT_LT(std::fabs(p.z - start.z), 0.2f * (p.x - start.x));  // along the wave, not across it
}

TEST(Water, SplashSheetsAllFallBackWithinSeconds) {
    Harbour h(make_test_level());
    drop(h, kDroppedStone, {45.0f, 4.0f, 25.0f});
    drop(h, kDroppedFloat, {47.0f, 4.0f, 25.0f});
    int last_splash = -1, t = 0;
    bool any_airborne = false;
    for (; t < 600; ++t) {
        h.world.step({});
        if (!h.water->splashes().empty()) last_splash = t;
        bool active = false;
        for (const sim::SplashSheet& s : h.water->sheets()) active = active || s.active();
        any_airborne = any_airborne || active;
        if (last_splash >= 0 && !active) break;
    }
    EXPECT_TRUE(any_airborne);
    EXPECT_LT(t - last_splash, 180) << "sheets still in the air 3 s after the last splash";
    for (const sim::SplashSheet& s : h.water->sheets()) {
        for (size_t k = 0; k < s.positions().size(); ++k) ASSERT_EQ(s.airborne()[k], 0);
    }
}

sim::LevelDesc level_with_car_by_the_boat() {
    sim::LevelDesc l = make_test_level();
    l.car_spawn.position = {36.0f, 1.0f, 30.0f};  // the player can step across to the boat
    return l;
}

TEST(Water, BoatAtRestRidesAtItsWaterline) {
    Harbour h(make_test_level());
    const sim::Boat& boat = h.world.get<sim::Boat>();
    for (int t = 0; t < 120; ++t) h.world.step({});
    drop(h, kDroppedStone, {43.0f, 4.0f, 30.0f});  // waves running under the hull
    drop(h, kDroppedStone, {40.0f, 4.0f, 35.0f});
    float worst = 0.0f, swing = 0.0f, pitch = 0.0f, roll = 0.0f;
    for (int t = 0; t < 360; ++t) {
        h.world.step({});
        pitch = std::max(pitch, std::fabs(boat.pose().pitch_rad));
        roll = std::max(roll, std::fabs(boat.pose().roll_rad));
        float water = 0.0f;
        for (int k = 0; k < sim::Boat::kHullPoints; ++k) {
            glm::vec2 hp = boat.hull_point(k);
            glm::vec3 w = boat.position() + boat.pose().forward_flat() * hp.x + boat.pose().right_flat() * hp.y;
            water += h.water->height_at({w.x, w.z}) / float(sim::Boat::kHullPoints);
        }
        worst = std::max(worst, std::fabs(boat.position().y - water));
        swing = std::max(swing, std::fabs(water));
    }
    EXPECT_LT(worst, 0.03f);
    EXPECT_GT(swing, 0.002f);  // the water under it did move
    EXPECT_GT(pitch, 0.002f);  // and it rocked with it
    EXPECT_GT(roll, 0.002f);
    EXPECT_NEAR(boat.position().x, 40.0f, 0.05f);
}

TEST(Water, BoatAtSpeedThrowsContinuousBowSpray) {
    Harbour h(level_with_car_by_the_boat());
    h.world.step(TickInput{uint16_t(Control::SwitchVehicle)});
    ASSERT_EQ(h.world.get<sim::Player>().vehicle(), sim::Vehicle::Boat);
    TickInput throttle;
    throttle.set(Control::Throttle, true);
    int ticks_with_spray = 0, ticks_with_sheet = 0, fast_ticks = 0;
    float behind = 0.0f;
    double emitted = 0.0, expected = 0.0;
    const float per_m = h.water->params().bow_spray_per_m;
    for (int t = 0; t < 420; ++t) {
        h.world.step(throttle);
        const float u = h.world.get<sim::Boat>().speed_mps();
        if (u < 4.0f) continue;
        ++fast_ticks;
        // Droplets born this tick have flown one step; the rule gives per_m * u * dt.
        // (Scraps torn off the bow's sheet, a size of their own, come on top.)
        int born = 0;
        for (const sim::SprayParticle& q : h.water->spray().particles())
            born += int(q.age_s < 1.5f * kDt && q.radius_m != h.water->params().sheet.torn_drop_radius_m);
        if (born >= int(per_m * u * kDt)) ++ticks_with_spray;
        emitted += born;
        expected += per_m * u * kDt;
        int k = h.water->bow_sheet();
        if (k < 0) continue;
        const sim::SplashSheet& sheet = h.water->sheets()[size_t(k)];
        if (sheet.airborne_count() > 0) ++ticks_with_sheet;
        // The sheet rides at the bow: nothing of it trails behind along the path.
        const sim::Pose& pose = h.world.get<sim::Boat>().pose();
        glm::vec3 bow = pose.position + pose.forward_flat() * (0.5f * h.world.get<sim::Boat>().params().length_m);
        for (size_t v = 0; v < sheet.positions().size(); ++v)
            if (sheet.airborne()[v]) behind = std::max(behind, glm::dot(bow - sheet.positions()[v], pose.forward_flat()));
    }
    EXPECT_LT(behind, 1.0f);
    ASSERT_GT(fast_ticks, 200);
    EXPECT_EQ(ticks_with_spray, fast_ticks);  // every tick at least the whole part of the rate
    EXPECT_NEAR(emitted / expected, 1.0, 0.1) << emitted << " droplets, " << expected << " by the rule";
    EXPECT_EQ(ticks_with_sheet, fast_ticks);
    // Its wake: the water behind the boat moves.
    glm::vec3 b = h.world.get<sim::Boat>().position();
    float wake = 0.0f;
    for (float back = 3.0f; back < 20.0f; back += 0.5f) wake = std::max(wake, std::fabs(h.water->height_at({b.x, b.z - back})));
    EXPECT_GT(wake, 0.01f);
}

TEST(Water, RainDimplesTheSurfaceOnlyWhenItRains) {
    sim::LevelDesc wet = make_test_level();
    wet.rain_intensity = 1.0f;
    Harbour dry(make_test_level()), rain(wet);
    for (int t = 0; t < 60; ++t) {
        dry.world.step({});
        rain.world.step({});
    }
    const auto& still = dry.water->grid().heights();
    EXPECT_TRUE(std::all_of(still.begin(), still.end(), [](float y) { return y == 0.0f; }));
    const auto& dimpled = rain.water->grid().heights();
    size_t moved = size_t(std::count_if(dimpled.begin(), dimpled.end(), [](float y) { return std::fabs(y) > 1e-5f; }));
    EXPECT_GT(moved, 1000u);
    EXPECT_LT(*std::max_element(dimpled.begin(), dimpled.end()), 0.01f);  // tiny
}

TEST(Water, LandCellsComeFromTheTerrain) {
    sim::WaterParams p;
    p.grid.origin_xz = {-40.0f, -10.0f};  // the grid reaches up onto the quay
    sim::WaterSim w(p, make_test_level(), 1);
    const sim::WaveGrid& g = w.grid();
    EXPECT_EQ(g.land_mask()[size_t(0)], 1);                                // z = -10: land
    EXPECT_EQ(g.land_mask()[size_t(19) * size_t(g.size())], 1);           // z = -0.5
    EXPECT_EQ(g.land_mask()[size_t(22) * size_t(g.size())], 0);           // z = 1: sea
    EXPECT_FLOAT_EQ(w.height_at({0.0f, 40.0f}), 0.0f);
    p.max_sheets = 0;
    std::string msg = message_of([&] { sim::WaterSim bad(p, make_test_level(), 1); });
    EXPECT_NE(msg.find("max_sheets"), std::string::npos) << msg;
    p = {};
    p.grid.wave_speed_mps = 100.0f;
    msg = message_of([&] { sim::WaterSim bad(p, make_test_level(), 1); });
    EXPECT_NE(msg.find("<= 0.5"), std::string::npos) << msg;
}

// Boat driving with turns, both kinds of throws, rain: everything the water does.
TickInput busy_input(uint32_t t) {
    TickInput in;
    in.set(Control::SwitchVehicle, t == 0);
    in.set(Control::Throttle, t > 2 && (t / 150) % 3 != 2);
    in.set(Control::Brake, (t / 150) % 3 == 2);
    in.set((t / 100) % 2 ? Control::SteerLeft : Control::SteerRight, t % 100 < 30);
    in.set(Control::ThrowHeavy, t % 23 == 3);
    in.set(Control::ThrowLight, t % 29 == 7);
    in.set(Control::RainUp, t % 200 == 5);
    return in;
}

std::vector<uint64_t> water_hashes(int threads, uint32_t ticks) {
    Harbour h(level_with_car_by_the_boat(), threads);
    std::vector<uint64_t> out;
    for (uint32_t t = 0; t < ticks; ++t) {
        h.world.step(busy_input(t));
        out.push_back(h.world.hash().world);
    }
    EXPECT_GT(h.water->spray().particles().size(), 10u);
    return out;
}

TEST(Water, SameHashesForOneAndTwoThreads) {
    auto one = water_hashes(1, 500);
    auto two = water_hashes(2, 500);
    ASSERT_EQ(one.size(), two.size());
    for (size_t t = 0; t < one.size(); ++t) ASSERT_EQ(one[t], two[t]) << "first differs at tick " << t;
}

}  // namespace
