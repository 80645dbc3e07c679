#include "sim/water/WaterSim.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/core/NumberText.h"
#include "sim/vehicle/Boat.h"
#include "sim/weather/Weather.h"
#include "sim/world/Terrain.h"
#include "sim/world/World.h"

namespace sim {

namespace {

constexpr float kPi = 3.14159265f;
constexpr float kWaterDensity = 1000.0f;
// Volume under WaveGrid::push's raised cosine of unit depth: pi R^2 (1/2 - 2/pi^2).
constexpr float kPushVolumePerR2 = kPi * (0.5f - 2.0f / (kPi * kPi));
// Wake: depth pushed per tick at each of three hull points is this times speed * dt,
// which gives a trough of about 10 cm along the path of a boat at 10 m/s.
constexpr float kWakeDepthPerSpeed_s = 0.024f;
constexpr float kRainDimple_m = 0.002f;
constexpr uint64_t kWaterStream = 0x5741544552ull;  // "WATER": the water's own PCG32 stream

bool finite3(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

const WaterParams& checked(const WaterParams& p) {
    auto refuse = [](const std::string& what) { throw std::invalid_argument("WaterSim: " + what); };
    auto in = [](float v, float lo, float hi) { return v >= lo && v <= hi; };
    if (p.max_sheets < 1 || p.max_sheets > 64) refuse("max_sheets must be 1..64, got " + std::to_string(p.max_sheets));
    if (!in(p.boat_wake_strength, 0.0f, 100.0f))
        refuse("boat_wake_strength must be in [0, 100], got " + num(p.boat_wake_strength));
    if (!in(p.rain_dimple_strength, 0.0f, 100.0f))
        refuse("rain_dimple_strength must be in [0, 100], got " + num(p.rain_dimple_strength));
    if (!in(p.land_clearance_m, -100.0f, 100.0f))
        refuse("land_clearance_m must be in [-100, 100], got " + num(p.land_clearance_m));
    if (!in(p.impact_push_scale, 0.0f, 100.0f))
        refuse("impact_push_scale must be in [0, 100], got " + num(p.impact_push_scale));
    if (!in(p.second_splash_min_s, 0.0f, 10.0f) || !in(p.second_splash_max_s, p.second_splash_min_s, 10.0f))
        refuse("second splash delays must satisfy 0 <= min <= max <= 10 s, got min " + num(p.second_splash_min_s) +
               ", max " + num(p.second_splash_max_s));
    if (!in(p.spray_per_momentum, 0.0f, 1000.0f))
        refuse("spray_per_momentum must be in [0, 1000], got " + num(p.spray_per_momentum));
    if (p.max_spray_per_impact < 0 || p.max_spray_per_impact > 100000)
        refuse("max_spray_per_impact must be 0..100000, got " + std::to_string(p.max_spray_per_impact));
    if (!in(p.bow_spray_min_speed_mps, 0.0f, 1000.0f))
        refuse("bow_spray_min_speed_mps must be in [0, 1000], got " + num(p.bow_spray_min_speed_mps));
    if (!in(p.bow_spray_mass_kg, 0.0f, 1e6f))
        refuse("bow_spray_mass_kg must be in [0, 1e6], got " + num(p.bow_spray_mass_kg));
    if (!in(p.bow_spray_per_m, 0.0f, 100000.0f))
        refuse("bow_spray_per_m must be in [0, 100000], got " + num(p.bow_spray_per_m));
    if (!in(p.rain_dimples_per_s, 0.0f, 1e6f))
        refuse("rain_dimples_per_s must be in [0, 1e6], got " + num(p.rain_dimples_per_s));
    return p;
}

}  // namespace

WaterSim::WaterSim(const WaterParams& params, const LevelDesc& level, uint64_t seed)
    : params_(checked(params)),
      sea_level_m_(level.sea_level_m),
      dt_(kTickSeconds),
      grid_(params.grid, kTickSeconds),
      sheets_(size_t(params.max_sheets), SplashSheet(params.sheet)),
      slots_(size_t(params.max_sheets)),
      spray_(params.spray),
      rng_(seed, kWaterStream) {
    if (!std::isfinite(sea_level_m_)) throw std::invalid_argument("WaterSim: the level's sea level is not finite");
    // Land where the terrain stands above the sea (less a clearance for the quay slope).
    const Terrain terrain(level);
    const int n = grid_.size();
    std::vector<uint8_t> land(size_t(n) * size_t(n), 0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            glm::vec2 xz = grid_.origin() + glm::vec2(float(i), float(j)) * grid_.spacing();
            land[size_t(j) * size_t(n) + size_t(i)] =
                uint8_t(terrain.ground_height(xz) > sea_level_m_ - params_.land_clearance_m);
        }
    grid_.set_land_mask(std::move(land));
    for (SplashSheet& s : sheets_) s.reset(glm::vec2(0.0f), grid_, sea_level_m_);
}

float WaterSim::height_at(glm::vec2 xz) const { return sea_level_m_ + grid_.sample(xz); }

int WaterSim::bow_sheet() const {
    for (size_t k = 0; k < slots_.size(); ++k)
        if (slots_[k].bow) return int(k);
    return -1;
}

int WaterSim::take_sheet(uint64_t tick) {
    int best = -1;
    for (size_t k = 0; k < slots_.size(); ++k)
        if (!sheets_[k].active() && !slots_[k].bow && !slots_[k].second_pending) {
            best = int(k);
            break;
        }
    if (best < 0)
        for (size_t k = 0; k < slots_.size(); ++k) {
            if (slots_[k].bow) continue;
            if (best < 0 || slots_[k].started_tick < slots_[size_t(best)].started_tick) best = int(k);
        }
    if (best < 0) best = 0;  // a single sheet, riding the bow: the impact takes it
    slots_[size_t(best)] = SheetSlot{};
    slots_[size_t(best)].started_tick = tick;
    return best;
}

void WaterSim::rain(float intensity) {
    if (!(intensity > 0.0f)) return;
    // Whole dimples this tick: the expected count, rounded up or down at random.
    float expected = std::min(intensity, 1.0f) * params_.rain_dimples_per_s * dt_;
    int count = int(expected + rng_.unit());
    const float extent = float(grid_.size() - 1) * grid_.spacing();
    const float depth = kRainDimple_m * params_.rain_dimple_strength;
    for (int k = 0; k < count; ++k) {
        float x = grid_.origin().x + rng_.unit() * extent;
        float z = grid_.origin().y + rng_.unit() * extent;
        grid_.push({x, z}, grid_.spacing(), depth);
    }
}

void WaterSim::second_splashes() {
    for (size_t k = 0; k < slots_.size(); ++k) {
        SheetSlot& s = slots_[k];
        if (!s.second_pending) continue;
        ++s.ticks_since_impact;
        const float t = float(s.ticks_since_impact) * dt_;
        const float centre = grid_.sample({s.impact.x, s.impact.z});
        const bool refilled = centre >= 0.25f * std::min(s.dip_m, 0.0f);
        if ((t >= params_.second_splash_min_s && refilled) || t >= params_.second_splash_max_s) {
            s.second_pending = false;
            sheets_[k].second_splash(s.object_radius_m, s.momentum_kgmps, rng_, grid_, sea_level_m_);
            glm::vec3 at(s.impact.x, height_at({s.impact.x, s.impact.z}), s.impact.z);
            splashes_.push_back(
                {SplashEvent::Kind::Second, at, sheets_[k].launch_speed(s.momentum_kgmps), int(k)});
        }
    }
}

void WaterSim::impact(const WaterEntry& e, uint64_t tick) {
    if (!finite3(e.position) || !finite3(e.velocity) || !std::isfinite(e.radius_m) || !std::isfinite(e.mass_kg))
        throw std::logic_error("WaterSim: a water entry has a non-finite position, velocity, radius or mass");
    const glm::vec2 xz(e.position.x, e.position.z);
    const float r = std::clamp(e.radius_m, 0.01f, 10.0f);
    const float mass = std::max(e.mass_kg, 0.0f);
    // Ring wave: push the surface down by the water the body displaces, all of its
    // volume if it goes under, the water equal to its mass if it floats.
    const float sphere = 4.0f / 3.0f * kPi * r * r * r;
    const float displaced = e.sinks ? sphere : std::min(sphere, mass / kWaterDensity);
    const float push_r = std::max(2.0f * r, 1.5f * grid_.spacing());
    grid_.push(xz, push_r, params_.impact_push_scale * displaced / (kPushVolumePerR2 * push_r * push_r));

    const float speed = std::sqrt(e.velocity.x * e.velocity.x + e.velocity.y * e.velocity.y +
                                  e.velocity.z * e.velocity.z);
    const float momentum = mass * speed;
    const int k = take_sheet(tick);
    SplashSheet& sheet = sheets_[size_t(k)];
    sheet.reset(xz, grid_, sea_level_m_);
    sheet.first_splash(r, momentum, rng_, grid_, sea_level_m_);
    const glm::vec3 at(e.position.x, height_at(xz), e.position.z);
    splashes_.push_back({SplashEvent::Kind::First, at, sheet.launch_speed(momentum), k});

    float wanted = std::min(params_.spray_per_momentum * momentum, float(params_.max_spray_per_impact));
    spray_.emit_splash(at, r, e.velocity, int(wanted), rng_);

    SheetSlot& s = slots_[size_t(k)];
    s.second_pending = e.sinks;
    s.object_radius_m = r;
    s.momentum_kgmps = momentum;
    s.dip_m = grid_.sample(xz);
    s.impact = at;
}

void WaterSim::boat(const Boat& b, uint64_t tick) {
    const Pose& pose = b.pose();
    const glm::vec3 vel = b.velocity();
    const float speed = std::sqrt(vel.x * vel.x + vel.z * vel.z);
    const glm::vec3 fwd = pose.forward_flat();
    const float length = b.params().length_m, beam = b.params().beam_m;
    // Wake: the hull pushes the surface down along its length, in proportion to speed;
    // moving, the pushes leave the V of ring fronts behind it.
    if (speed > 0.05f) {
        const float depth = params_.boat_wake_strength * kWakeDepthPerSpeed_s * speed * dt_;
        for (float along : {0.35f * length, 0.0f, -0.35f * length}) {
            glm::vec3 p = pose.position + fwd * along;
            grid_.push({p.x, p.z}, 0.5f * beam, depth);
        }
    }

    // Bow spray: the first-splash rule applied every tick at the bow, to the vertices
    // ahead of it only (seed 4.2.4), on a sheet that rides with the bow.
    int k = bow_sheet();
    const float u = b.speed_mps();
    if (!(u > 0.0f && u >= params_.bow_spray_min_speed_mps)) {
        if (k >= 0) slots_[size_t(k)].bow = false;  // left to fall back where it is
        return;
    }
    const glm::vec3 bow = pose.position + fwd * (0.5f * length);
    const glm::vec2 bow_xz(bow.x, bow.z);
    if (k < 0) {
        k = take_sheet(tick);
        slots_[size_t(k)].bow = true;
        sheets_[size_t(k)].reset(bow_xz, grid_, sea_level_m_);
    }
    SplashSheet& sheet = sheets_[size_t(k)];
    sheet.move_to(bow_xz);
    const glm::vec2 ahead = glm::vec2(fwd.x, fwd.z) / std::sqrt(fwd.x * fwd.x + fwd.z * fwd.z);
    const float ring = 0.25f * beam;
    sheet.first_splash(ring, params_.bow_spray_mass_kg * u, rng_, grid_, sea_level_m_, ahead, {vel.x, vel.z});
    int count = int(params_.bow_spray_per_m * u * dt_ + rng_.unit());
    spray_.emit_splash({bow.x, height_at(bow_xz), bow.z}, ring, vel, count, rng_, ahead);
}

void WaterSim::connect(const SubsystemLinks& links) {
    weather_ = links.may<Weather>();
    boat_ = links.may<Boat>();
}

void WaterSim::step(StepContext& ctx) {
    if (ctx.dt != dt_)
        throw std::logic_error("WaterSim: the wave grid was built for dt = " + num(dt_) + " s, stepped with " +
                               num(ctx.dt) + " s");
    splashes_.clear();
    ripples_.clear();
    if (weather_) rain(weather_->rain_rate());
    second_splashes();
    for (const WaterEntry& e : ctx.world.events().water_entries) impact(e, ctx.tick);
    if (boat_) boat(*boat_, ctx.tick);

    grid_.step(ctx.jobs);
    for (SplashSheet& s : sheets_) {
        s.step(dt_, grid_, sea_level_m_, ripples_);
        for (const TornOff& t : s.torn()) spray_.emit({t.position, t.velocity, params_.sheet.torn_drop_radius_m, 0.0f});
    }
    spray_.step(dt_, grid_, sea_level_m_, ripples_, &ctx.jobs);
    // What fell back in rings the water (seed 4.4), in a fixed order.
    for (const Ripple& r : ripples_) grid_.push(r.xz, grid_.spacing(), r.depth_m);
}


}  // namespace sim
