#include "sim/rain/RainSim.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/core/DetMath.h"
#include "sim/core/NumberText.h"
#include "sim/player/Player.h"
#include "sim/vehicle/Car.h"
#include "sim/weather/Weather.h"
#include "sim/world/World.h"

namespace sim {

namespace {

constexpr float kPi = 3.14159265f;
constexpr float kGravity = 9.81f;
constexpr uint64_t kRainStream = 0x5241494eull;  // "RAIN"
// The eight neighbour steps, counter-clockwise from +u.
constexpr int kStepU[8] = {1, 1, 0, -1, -1, -1, 0, 1};
constexpr int kStepV[8] = {0, 1, 1, 1, 0, -1, -1, -1};

const RainParams& checked(const RainParams& p) {
    auto refuse = [](const std::string& what) { throw std::invalid_argument("rain: " + what); };
    auto in = [](float v, float lo, float hi) { return v >= lo && v <= hi; };  // false for NaN
    if (!in(p.cell_size_m, kMinRainCell_m, kMaxRainCell_m))
        refuse("cell_size_m must be in [" + num(kMinRainCell_m) + ", " + num(kMaxRainCell_m) + "] m, got " + num(p.cell_size_m));
    if (!in(p.drops_per_m2_s, 0.0f, 1e5f)) refuse("drops_per_m2_s must be in [0, 1e5], got " + num(p.drops_per_m2_s));
    if (!in(p.speed_gain_per_mps, 0.0f, 10.0f)) refuse("speed_gain_per_mps must be in [0, 10], got " + num(p.speed_gain_per_mps));
    if (!in(p.new_drop_min_mg, 0.01f, 1000.0f) || !in(p.new_drop_max_mg, p.new_drop_min_mg, 1000.0f))
        refuse("new drop masses must satisfy 0.01 <= min <= max <= 1000 mg, got " + num(p.new_drop_min_mg) + " and " +
               num(p.new_drop_max_mg));
    if (!in(p.slide_mass_mg, 0.1f, 1e4f)) refuse("slide_mass_mg must be in [0.1, 1e4], got " + num(p.slide_mass_mg));
    if (!in(p.drag_per_s, 0.1f, 1000.0f)) refuse("drag_per_s must be in [0.1, 1000], got " + num(p.drag_per_s));
    if (!in(p.particle_mass_mg, 0.05f, 100.0f)) refuse("particle_mass_mg must be in [0.05, 100], got " + num(p.particle_mass_mg));
    if (!in(p.band_m, 0.0f, 1.0f)) refuse("band_m must be in [0, 1], got " + num(p.band_m));
    if (!in(p.restitution, 0.0f, 1.0f)) refuse("restitution must be in [0, 1], got " + num(p.restitution));
    if (p.collision_iterations < 0 || p.collision_iterations > 16)
        refuse("collision_iterations must be 0..16, got " + std::to_string(p.collision_iterations));
    if (!in(p.defer_mass_mg, 0.0f, 1e5f)) refuse("defer_mass_mg must be in [0, 1e5], got " + num(p.defer_mass_mg));
    if (p.defer_search_cells < 0 || p.defer_search_cells > 16)
        refuse("defer_search_cells must be 0..16, got " + std::to_string(p.defer_search_cells));
    for (float f : {p.trail_chance, p.trail_fraction, p.film_fraction})
        if (!in(f, 0.0f, 0.5f)) refuse("trail_chance, trail_fraction and film_fraction must be in [0, 0.5], got " + num(f));
    if (!in(p.trail_shrink_mg_per_s, 0.0f, 100.0f) || !in(p.trail_vanish_mg, 0.0f, 100.0f) || !in(p.trail_min_mg, 0.0f, 100.0f))
        refuse("trail masses and shrink rate must be in [0, 100]");
    if (!in(p.wet_affinity, 0.0f, 10.0f) || !in(p.wet_memory_s, 0.0f, 600.0f))
        refuse("wet_affinity must be in [0, 10] and wet_memory_s in [0, 600]");
    if (p.max_drops < 1 || p.max_drops > 1000000 || p.max_particles < 0 || p.max_particles > 1000000)
        refuse("max_drops must be 1..1e6 and max_particles 0..1e6");
    if (!(p.motor.low_cycle_s >= 0.1f && p.motor.high_cycle_s >= 0.1f && p.motor.intermittent_pause_s >= 0.0f))
        refuse("wiper cycles must be at least 0.1 s and the pause not negative");
    for (const WiperLayout& b : p.blades)
        if (!(b.inner >= 0.0f && b.outer > b.inner && b.outer < 4.0f) || !std::isfinite(b.pivot.x) ||
            !std::isfinite(b.pivot.y) || !std::isfinite(b.rest_rad) || !(std::fabs(b.sweep_rad) < 2.0f * kPi))
            refuse("a wiper blade needs 0 <= inner < outer < 4 and a sweep under a full turn");
    return p;
}

float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }
float dot(glm::vec2 a, glm::vec2 b) { return a.x * b.x + a.y * b.y; }
float dot3(glm::vec3 a, glm::vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
float len(glm::vec2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }

WiperBladeParams place(const WiperLayout& l, const GlassSurface& g) {
    WiperBladeParams b;
    b.pivot_m = {l.pivot.x * g.width_m(), l.pivot.y * g.height_m()};
    b.inner_m = l.inner * g.height_m();
    b.outer_m = l.outer * g.height_m();
    b.rest_rad = l.rest_rad;
    b.sweep_rad = l.sweep_rad;
    return b;
}

}  // namespace

float RainSim::radius_m(float mass_mg) { return 1e-3f * det::cbrt(3.0f * mass_mg / (2.0f * kPi)); }

RainSim::RainSim(const RainParams& params, std::vector<glm::vec3> glass_lower, std::vector<glm::vec3> glass_upper,
                 uint64_t seed)
    : p_(checked(params)),
      rng_(seed, kRainStream),
      glass_(std::move(glass_lower), std::move(glass_upper), p_.cell_size_m, rng_),
      blades_{WiperBlade(place(p_.blades[0], glass_)), WiperBlade(place(p_.blades[1], glass_))},
      cell_drop_(size_t(glass_.cell_count()), -1),
      wet_tick_(size_t(glass_.cell_count()), 0u),
      particle_r_m_(radius_m(p_.particle_mass_mg)),
      hold_ref_(kGravity * det::sin(0.25f * kPi)),
      slide_r_m_(radius_m(p_.slide_mass_mg)) {}

RainForces RainSim::forces_for(float speed_mps, glm::vec2 accel_body_mps2, glm::vec3 gravity_model) const {
    RainForces f;
    // In the car's frame the drops feel its acceleration backwards: braking sends them
    // forward, which on a raked windshield is down the glass. +z is the car's right,
    // the lateral acceleration is positive to the left (-z).
    f.body = gravity_model + glm::vec3(-accel_body_mps2.x, 0.0f, accel_body_mps2.y);
    const float over = std::max(std::fabs(speed_mps) - p_.air_start_mps, 0.0f);
    f.air = glm::vec3(speed_mps >= 0.0f ? -1.0f : 1.0f, 0.0f, 0.0f) * (p_.air_accel * over * over);
    return f;
}

void RainSim::connect(const SubsystemLinks& links) {
    player_ = links.may<Player>();
    car_ = links.may<Car>();
    weather_ = links.may<Weather>();
}

void RainSim::step(StepContext& ctx) {
    const float intensity = weather_ ? weather_->rain_rate() : 0.0f;
    const WiperMode wipers = player_ ? player_->wipers() : WiperMode::Off;
    RainForces forces = forces_for(0.0f, glm::vec2(0.0f), glm::vec3(0.0f, -kGravity, 0.0f));
    float speed = 0.0f;
    if (car_) {
        const glm::mat4 m = car_->pose().matrix();
        const glm::vec3 down(0.0f, -kGravity, 0.0f);  // world to model: the transposed rotation
        const glm::vec3 g(dot3(glm::vec3(m[0]), down), dot3(glm::vec3(m[1]), down), dot3(glm::vec3(m[2]), down));
        speed = car_->speed_mps();
        forces = forces_for(speed, car_->accel_body_mps2(), g);
    }
    const double added_before = ledger_.added_mg;
    advance(intensity, wipers, speed, forces, ctx.dt);
    ctx.world.report().glass_drops = landed_;
    ctx.world.report().glass_drop_mg = float(ledger_.added_mg - added_before);
}

void RainSim::advance(float intensity, WiperMode wipers, float car_speed_mps, const RainForces& forces, float dt) {
    if (!(intensity >= 0.0f) || !std::isfinite(intensity))
        throw std::invalid_argument("rain: intensity must be finite and not negative, got " + num(intensity));
    if (!(dt > 0.0f) || !std::isfinite(car_speed_mps))
        throw std::invalid_argument("rain: dt must be positive and the car speed finite");
    ++tick_;
    motor_.step(wipers, dt);
    for (WiperBlade& b : blades_) b.set_fraction(motor_.fraction());
    rain(intensity, car_speed_mps, dt);
    move_drops(forces, dt);
    for (const WiperBlade& b : blades_)
        if (b.turning() != 0.0f) sweep(b);
    if (!particles_.empty()) {
        push_particles(true);
        for (int k = 0; k < p_.collision_iterations; ++k) collider_.collide(particles_, particle_r_m_, p_.restitution);
        push_particles(false);  // the blade has the last word: nothing is left inside it
        particles_to_grid();
    }
    compact();
}

float RainSim::wetness(int cell) const {
    const uint32_t wet = wet_tick_[size_t(cell)];
    if (wet == 0 || p_.wet_memory_s <= 0.0f) return 0.0f;
    const float age_s = float(uint32_t(tick_) + 1u - wet) * (1.0f / 60.0f);
    return std::max(1.0f - age_s / p_.wet_memory_s, 0.0f);
}

float RainSim::affinity(int cell) const {
    return glass_.cell(cell).affinity + p_.wet_affinity * wetness(cell);
}

int32_t RainSim::new_drop(glm::vec2 pos_m, float mass_mg, uint32_t flags) {
    const int cell = glass_.cell_of(pos_m);
    const int32_t at = cell_drop_[size_t(cell)];
    if (at >= 0) {
        RainDrop& d = drops_[size_t(at)];
        d.vel_mps *= d.mass_mg / (d.mass_mg + mass_mg);
        d.mass_mg += mass_mg;
        d.radius_m = radius_m(d.mass_mg);
        d.flags &= ~RainDrop::kTrail;  // fed, it is a drop again
        return at;
    }
    RainDrop d;
    d.pos_m = pos_m;
    d.mass_mg = mass_mg;
    d.radius_m = radius_m(mass_mg);
    d.cell = cell;
    d.flags = flags;
    drops_.push_back(d);
    cell_drop_[size_t(cell)] = int32_t(drops_.size() - 1);
    return int32_t(drops_.size() - 1);
}

void RainSim::add_drop(glm::vec2 pos_m, float mass_mg) {
    if (!glass_.contains(pos_m) || !(mass_mg > 0.0f)) throw std::invalid_argument("rain: a drop must be on the glass with a positive mass");
    new_drop(pos_m, mass_mg, 0);
    ledger_.added_mg += mass_mg;
}

void RainSim::kill_drop(size_t i) {
    RainDrop& d = drops_[i];
    d.flags |= RainDrop::kDead;
    if (cell_drop_[size_t(d.cell)] == int32_t(i)) cell_drop_[size_t(d.cell)] = -1;
}

void RainSim::rain(float intensity, float car_speed_mps, float dt) {
    landed_ = 0;
    if (intensity <= 0.0f) return;
    const float area = glass_.width_m() * glass_.height_m();
    const float rate = intensity * p_.drops_per_m2_s * area * (1.0f + p_.speed_gain_per_mps * std::fabs(car_speed_mps));
    const int count = int(rate * dt + rng_.unit());
    const glm::vec2 extent = glm::vec2(float(glass_.cols()), float(glass_.rows())) * glass_.cell_m();
    for (int k = 0; k < count; ++k) {
        const glm::vec2 pos = rng_.unit2() * extent;
        float mass = rng_.range(p_.new_drop_min_mg, p_.new_drop_max_mg);
        if (int(drops_.size()) >= p_.max_drops && cell_drop_[size_t(glass_.cell_of(pos))] < 0) continue;  // full
        new_drop(pos, mass, 0);
        ledger_.added_mg += mass;
        ++landed_;
    }
}

void RainSim::move_drops(const RainForces& forces, float dt) {
    for (size_t i = 0; i < drops_.size(); ++i) {
        if (drops_[i].dead()) continue;
        if (drops_[i].trail()) {
            RainDrop& d = drops_[i];
            const float lost = std::min(d.mass_mg, p_.trail_shrink_mg_per_s * dt);
            d.mass_mg -= lost;
            d.radius_m = radius_m(d.mass_mg);
            ledger_.evaporated_mg += lost;
            if (d.mass_mg <= p_.trail_vanish_mg) {
                ledger_.evaporated_mg += d.mass_mg;
                d.mass_mg = 0.0f;
                kill_drop(i);
            }
            continue;
        }
        RainDrop& d = drops_[i];
        const GlassCell& c = glass_.cell(d.cell);
        // Per unit mass: gravity and inertia as they are, air by area over mass (1 / r),
        // holding by contact line over mass (1 / r^2), stronger on high affinity.
        const float rr = slide_r_m_ / d.radius_m;
        const glm::vec3 f = forces.body + forces.air * rr;
        const glm::vec2 a(dot3(f, c.tangent_u), dot3(f, c.tangent_v));
        const float drive = len(a);
        const float hold = hold_ref_ * rr * rr * (0.7f + 0.6f * c.affinity);
        if (drive <= hold) {
            d.vel_mps = glm::vec2(0.0f);
            d.travel_m = 0.0f;
            continue;
        }
        const glm::vec2 acc = a * ((drive - hold) / drive);
        d.vel_mps = (d.vel_mps + acc * dt) / (1.0f + p_.drag_per_s * dt);
        d.travel_m += len(d.vel_mps) * dt;
        while (drops_[i].travel_m >= glass_.cell_m() && !drops_[i].dead())
            if (!step_cell(i)) break;
    }
}

bool RainSim::step_cell(size_t i) {
    RainDrop d = drops_[i];
    // The three cells ahead of the velocity, weighted by affinity and straightness.
    const float angle = det::atan2(d.vel_mps.y, d.vel_mps.x);
    const int ahead = (int(std::floor(angle / (0.25f * kPi) + 0.5f)) % 8 + 8) % 8;
    const glm::ivec2 at = glass_.cell_xy(d.cell);
    int choice[3];
    float weight[3], total = 0.0f;
    for (int k = 0; k < 3; ++k) {
        const int dir = (ahead + k + 7) % 8;
        choice[k] = dir;
        const int ci = at.x + kStepU[dir], cj = at.y + kStepV[dir];
        const bool on = ci >= 0 && cj >= 0 && ci < glass_.cols() && cj < glass_.rows();
        const float aff = on ? affinity(cj * glass_.cols() + ci) : 0.5f;
        weight[k] = (0.05f + aff) * (k == 1 ? p_.straight_weight : p_.side_weight);
        total += weight[k];
    }
    float pick = rng_.unit() * total;
    int dir = choice[2];
    for (int k = 0; k < 3; ++k) {
        if (pick < weight[k]) {
            dir = choice[k];
            break;
        }
        pick -= weight[k];
    }
    const int ci = at.x + kStepU[dir], cj = at.y + kStepV[dir];
    const float step_m = glass_.cell_m() * ((kStepU[dir] != 0 && kStepV[dir] != 0) ? 1.41421356f : 1.0f);
    d.travel_m = std::max(d.travel_m - step_m, 0.0f);
    const int from = d.cell;
    if (ci < 0 || cj < 0 || ci >= glass_.cols() || cj >= glass_.rows()) {
        ledger_.drained_mg += d.mass_mg;
        drops_[i] = d;
        kill_drop(i);
        return false;
    }
    const int to = cj * glass_.cols() + ci;
    d.pos_m += glm::vec2(float(kStepU[dir]), float(kStepV[dir])) * glass_.cell_m();
    d.cell = to;
    wet_tick_[size_t(to)] = uint32_t(tick_) + 1u;
    cell_drop_[size_t(from)] = -1;

    // A trailing drop in the cell just left, now and then.
    float trail_mass = 0.0f;
    if (d.mass_mg * p_.trail_fraction >= p_.trail_min_mg && rng_.unit() < p_.trail_chance) {
        trail_mass = d.mass_mg * p_.trail_fraction;
        d.mass_mg -= trail_mass;
    }
    const int32_t other = cell_drop_[size_t(to)];
    if (other >= 0) {  // merge: the mover takes the resting drop in
        RainDrop& o = drops_[size_t(other)];
        d.vel_mps *= d.mass_mg / (d.mass_mg + o.mass_mg);
        d.mass_mg += o.mass_mg;
        o.mass_mg = 0.0f;
        kill_drop(size_t(other));
    }
    if (trail_mass > 0.0f || other >= 0) d.radius_m = radius_m(d.mass_mg);
    drops_[i] = d;
    cell_drop_[size_t(to)] = int32_t(i);
    if (trail_mass > 0.0f) {
        glm::vec2 jitter = (rng_.unit2() - 0.5f) * (0.6f * glass_.cell_m());
        new_drop(glass_.centre(from) + jitter, trail_mass, RainDrop::kTrail);
    }
    return true;
}

void RainSim::sweep(const WiperBlade& blade) {
    const WiperBladeParams& bp = blade.params();
    const float turn = blade.turning();
    const glm::vec2 now = blade.direction(), before = blade.previous_direction();
    const glm::vec2 mid = now + before, mid_unit = mid / len(mid);
    const float sector_half_width = std::fabs(cross(before, now)) * bp.outer_m + 0.03f;
    const size_t count = drops_.size();  // not the film drops this sweep leaves
    for (size_t i = 0; i < count; ++i) {
        if (drops_[i].dead()) continue;
        const RainDrop d = drops_[i];
        const glm::vec2 rel = d.pos_m - bp.pivot_m;
        // Cheap test first: the sector lies within outer * sin(sweep) (+ any drop's reach)
        // of its bisector.
        if (std::fabs(cross(mid_unit, rel)) > sector_half_width) continue;
        const float r = d.radius_m;
        const float reach = r + bp.half_width_m;
        const float rho2 = dot(rel, rel);
        if (rho2 > (bp.outer_m + reach) * (bp.outer_m + reach) || rho2 < (bp.inner_m - reach) * (bp.inner_m - reach))
            continue;
        // Inside the sector the blade swept this tick, widened by the drop and the rubber.
        if (turn * cross(before, rel) < -reach || turn * cross(now, rel) > reach || dot(rel, mid) <= 0.0f) continue;

        // Touched: a film stays behind, the rest becomes uniform particles.
        float mass = d.mass_mg;
        kill_drop(i);
        drops_[i].mass_mg = 0.0f;
        const float film = mass * p_.film_fraction;
        if (film >= p_.trail_vanish_mg * 2.0f) {
            mass -= film;
            new_drop(d.pos_m, film, RainDrop::kTrail);
        }
        const int room = p_.max_particles - int(particles_.size());
        const int n = std::clamp(int(mass / p_.particle_mass_mg + 0.5f), 1, std::max(room, 1));
        const float each = mass / float(n);
        for (int k = 0; k < n; ++k) {
            glm::vec2 at = d.pos_m;
            if (k > 0) at += (rng_.unit2() - 0.5f) * (2.0f * r);
            particles_.push_back({at, each, 0u});
        }
    }
}

void RainSim::push_particles(bool carry) {
    // A particle the blade reached goes out along the blade's normal to touch it. When
    // the blade moves on (carry), a particle that was already ahead of it, in the bead,
    // keeps its distance ahead: the bead is pushed along as a whole, layers and all,
    // not flattened against the rubber.
    const float contact = particle_r_m_;
    for (const WiperBlade& b : blades_) {
        const WiperBladeParams& bp = b.params();
        const glm::vec2 now = b.direction(), before = b.previous_direction(), normal(-now.y, now.x);
        const float turn = b.turning(), reach = bp.half_width_m + contact;
        for (WaterParticle& q : particles_) {
            const glm::vec2 rel = q.pos_m - bp.pivot_m;
            const float along = dot(rel, now);
            if (along < bp.inner_m || along > bp.outer_m) continue;  // past the ends: spills
            const float s = cross(now, rel);
            float side = turn, target = reach;
            if (turn == 0.0f) {
                if (std::fabs(s) >= reach) continue;
                side = s >= 0.0f ? 1.0f : -1.0f;
            } else {
                const float ahead_before = side * cross(before, rel) - reach;
                if (side * s >= reach || ahead_before < -reach) continue;  // not reached, or behind where it started
                if (carry) target = reach + std::max(ahead_before, 0.0f);
            }
            q.pos_m += normal * (side * target - s);
        }
    }
}

bool RainSim::near_blade(glm::vec2 pos_m, float reach_m) const {
    for (const WiperBlade& b : blades_) {
        const WiperBladeParams& bp = b.params();
        const glm::vec2 rel = pos_m - bp.pivot_m, dir = b.direction();
        const float along = dot(rel, dir);
        if (along < bp.inner_m - reach_m || along > bp.outer_m + reach_m) continue;
        if (std::fabs(cross(dir, rel)) <= reach_m) return true;
    }
    return false;
}

void RainSim::particles_to_grid() {
    const int reach = p_.defer_search_cells;
    // Which cells hold a drop heavy enough to defer a conversion near it, kept up to
    // date as particles join drops: the search reads bytes, not drops.
    heavy_.resize(cell_drop_.size());
    for (size_t c = 0; c < cell_drop_.size(); ++c)
        heavy_[c] = cell_drop_[c] >= 0 && drops_[size_t(cell_drop_[c])].mass_mg > p_.defer_mass_mg;
    for (WaterParticle& q : particles_) {
        if (!glass_.contains(q.pos_m)) {  // pushed off the edge of the glass
            ledger_.drained_mg += q.mass_mg;
            q.dead = 1;
            continue;
        }
        if (near_blade(q.pos_m, p_.band_m)) continue;
        // Deferred while a big drop sits in the square around the target cell, so that a
        // reversal does not pour the whole bead into one giant drop.
        const int cell = glass_.cell_of(q.pos_m);
        const glm::ivec2 c = glass_.cell_xy(cell);
        bool defer = false;
        for (int j = std::max(c.y - reach, 0); j <= std::min(c.y + reach, glass_.rows() - 1) && !defer; ++j)
            for (int i = std::max(c.x - reach, 0); i <= std::min(c.x + reach, glass_.cols() - 1); ++i)
                defer |= heavy_[size_t(j * glass_.cols() + i)] != 0;
        if (defer) continue;
        const int32_t at = new_drop(q.pos_m, q.mass_mg, 0);
        heavy_[size_t(cell)] = drops_[size_t(at)].mass_mg > p_.defer_mass_mg;
        q.dead = 1;
    }
}

void RainSim::compact() {
    size_t kept = 0;
    for (size_t i = 0; i < drops_.size(); ++i) {
        if (drops_[i].dead()) continue;
        if (kept != i) drops_[kept] = drops_[i];
        cell_drop_[size_t(drops_[kept].cell)] = int32_t(kept);
        ++kept;
    }
    drops_.resize(kept);
    particles_.erase(std::remove_if(particles_.begin(), particles_.end(), [](const WaterParticle& q) { return q.dead != 0; }),
                     particles_.end());
}

double RainSim::mass_on_glass_mg() const {
    double m = 0.0;
    for (const RainDrop& d : drops_) m += d.mass_mg;
    for (const WaterParticle& q : particles_) m += q.mass_mg;
    return m;
}


}  // namespace sim
