#include "audio/Soundscape.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

#include "audio/models/Cue.h"
#include "audio/models/Splash.h"
#include "sim/fluid/FluidTank.h"
#include "sim/player/CameraRig.h"
#include "sim/player/Player.h"
#include "sim/rain/RainSim.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/water/WaterSim.h"
#include "sim/weapon/Weapon.h"
#include "sim/weather/Weather.h"
#include "sim/world/World.h"

namespace audio {

namespace {
constexpr float kTick_s = 1.0f / 60.0f;
constexpr int kTickFrames = kSampleRate / 60;
constexpr float kFastestBlade_radps = 6.0f;
constexpr float kWetBlades_mg = 300.0f;    // water the blades meet: this much is a wet sweep
constexpr float kBladeWaterTau_s = 1.0f;   // about a sweep
// The water rising against the hull this fast slaps (a harbour's swell laps at a few
// cm/s; running into the chop, tenths of a m/s), full strength from kSlapHard_mps.
constexpr float kSlapRise_mps = 0.03f, kSlapHard_mps = 0.6f;

Placement at(glm::vec3 position, float reference_m, bool outside = true, float doppler = 1.0f) {
    return Placement{true, position, reference_m, outside, doppler};
}

Placement bed(bool outside) { return Placement{false, glm::vec3(0.0f), 1.0f, outside, 0.0f}; }

uint64_t shot_key(const sim::Shot& s) {
    uint32_t a, b;
    std::memcpy(&a, &s.phase, 4);
    std::memcpy(&b, &s.origin.x, 4);
    return uint64_t(a) << 32 | b;
}
}  // namespace

Listener listener_for(const sim::World& world, const sim::CameraView& presented) {
    Listener l;
    l.position = presented.eye;
    const glm::vec3 look = presented.target - presented.eye;
    const float len = std::sqrt(glm::dot(look, look));
    if (len > 1e-5f) l.forward = look / len;
    l.up = presented.up;
    const sim::Player* player = world.find<sim::Player>();
    const sim::CameraRig* rig = world.find<sim::CameraRig>();
    if (player && rig && player->vehicle() == sim::Vehicle::Car && player->view() == sim::ViewMode::Driver) {
        const glm::vec3 d = rig->view().eye - presented.eye;
        l.in_cabin = glm::dot(d, d) < 0.25f;
    }
    return l;
}

Soundscape::Soundscape(Mixer& mixer)
    : mixer_(mixer),
      engine_(Bus::Engine, EngineSound{4.0f, 4.0f, 380.0f, 1800.0f, 0.55f, 11}),
      boat_motor_(Bus::Engine, EngineSound{2.0f, 2.0f, 900.0f, 3200.0f, 0.4f, 23}),
      tyres_(Bus::Effects, NoiseBand{500.0f, 3500.0f, 0.0f, 0.0f, 0.5f, 31}),
      spray_(Bus::Effects, NoiseBand{1200.0f, 9000.0f, 2.5f, 0.4f, 0.3f, 37}),
      rain_bed_(Bus::Ambience, NoiseBand{700.0f, 11000.0f, 0.0f, 0.0f, 0.55f, 41}),
      wind_(Bus::Ambience, NoiseBand{120.0f, 900.0f, 0.12f, 0.6f, 0.45f, 43}),
      sea_(Bus::Ambience, NoiseBand{60.0f, 700.0f, 0.09f, 0.7f, 0.55f, 47}),
      slosh_(Bus::Effects, NoiseBand{150.0f, 1400.0f, 1.3f, 0.6f, 0.6f, 67}),
      sea_rain_(Bus::Ambience, 53),
      glass_(59),
      wipers_(61) {
    rain_bed_.place = bed(true);
    wind_.place = bed(true);
    sea_.place = bed(true);
    sea_rain_.place = bed(true);
    for (Voice* v : std::initializer_list<Voice*>{&engine_, &boat_motor_, &tyres_, &spray_, &rain_bed_, &wind_, &sea_,
                                                   &slosh_, &sea_rain_, &glass_, &wipers_})
        changes_.add(*v);
    mixer_.submit(std::move(changes_));
    changes_ = MixChanges();
}

Soundscape::~Soundscape() {
    mixer_.apply_changes();
    for (Voice* v : std::initializer_list<Voice*>{&engine_, &boat_motor_, &tyres_, &spray_, &rain_bed_, &wind_, &sea_,
                                                   &slosh_, &sea_rain_, &glass_, &wipers_})
        mixer_.remove(*v);
}

void Soundscape::strike(const StrikeSound& sound, const Placement& place) {
    auto v = std::make_unique<StrikeVoice>(Bus::Effects, sound);
    v->place = place;
    changes_.play(std::move(v));
}

void Soundscape::after_tick(const sim::World& world, const Listener& listener) {
    state_.events = 0;
    vehicles(world);
    weather(world, listener);
    wipers(world);
    shots(world);
    events(world);
    tank(world);
    hull(world);
    changes_.update_placement(listener, kTick_s);
    mixer_.submit(std::move(changes_));
    changes_ = MixChanges();
    first_tick_ = false;
}

void Soundscape::vehicles(const sim::World& world) {
    const sim::Player& player = world.get<sim::Player>();
    const sim::Car& car = world.get<sim::Car>();
    const sim::Boat& boat = world.get<sim::Boat>();
    const sim::Weather* weather = world.find<sim::Weather>();
    const float wet = weather ? weather->road_wetness() : 0.0f;

    // The car: rpm through the gearbox from the wheels' speed, load from the throttle.
    const sim::DriveInput car_in = player.drive_input(sim::Vehicle::Car);
    gearbox_.tick(car.speed_mps(), car_in.throttle, kTick_s);
    const bool in_car = player.vehicle() == sim::Vehicle::Car;
    const glm::vec3 car_fwd = car.pose().forward_flat();
    tell(engine_, [rpm = gearbox_.rpm(), load = gearbox_.load(), level = in_car ? 1.0f : 0.45f,
                   place = at(car.position() + car_fwd * 1.6f + glm::vec3(0.0f, 0.6f, 0.0f), 5.0f)](EngineVoice& v) {
        v.set(rpm, load, level);
        v.place = place;
    });
    state_.engine_rpm = gearbox_.rpm();
    state_.gear = gearbox_.gear();

    // Tyres: a hiss growing with speed, louder and brighter on a wet road.
    const float speed = std::fabs(car.speed_mps());
    tell(tyres_, [level = std::min(1.0f, std::pow(speed / 25.0f, 1.5f)) * (0.35f + 0.65f * wet),
                  high = 2500.0f + 5000.0f * wet, place = at(car.position(), 4.0f)](NoiseBed& v) {
        v.set(level, high);
        v.place = place;
    });

    // The boat: an outboard's two-stroke by throttle, the bow's spray by speed.
    const sim::DriveInput boat_in = player.drive_input(sim::Vehicle::Boat);
    const float boat_speed = std::fabs(boat.speed_mps());
    const float boat_target = 1100.0f + 4200.0f * std::max(boat_in.throttle, boat_in.brake * 0.5f) + 60.0f * boat_speed;
    boat_rpm_ += (boat_target - boat_rpm_) * 0.08f;
    const bool in_boat = player.vehicle() == sim::Vehicle::Boat;
    const glm::vec3 boat_fwd = boat.pose().forward_flat();
    tell(boat_motor_, [rpm = boat_rpm_, load = std::max(boat_in.throttle, boat_in.brake), level = in_boat ? 0.9f : 0.3f,
                       place = at(boat.position() - boat_fwd * 2.8f, 5.0f)](EngineVoice& v) {
        v.set(rpm, load, level);
        v.place = place;
    });
    tell(spray_, [level = std::min(1.0f, (boat_speed / 10.0f) * (boat_speed / 10.0f)),
                  place = at(boat.position() + boat_fwd * 2.5f, 5.0f)](NoiseBed& v) {
        v.set(level);
        v.place = place;
    });
}

void Soundscape::weather(const sim::World& world, const Listener& listener) {
    const sim::Weather* weather = world.find<sim::Weather>();
    const float rain = weather ? weather->rain_rate() : 0.0f;
    // The bed: the sum of countless distant drops, its level as the rain rate's 0.7 power.
    const float bed_level = rain > 0.0f ? std::pow(rain, 0.7f) : 0.0f;
    tell(rain_bed_, [bed_level](NoiseBed& v) { v.set(bed_level); });
    state_.rain_bed = bed_level;
    // Drops on the sea as bubbles, by rain rate (van den Doel's rain: radii 1-2.5 mm).
    tell(sea_rain_, [rain](BubbleVoice& v) { v.set_rain(900.0f * rain, 0.0011f, 0.0026f, 0.12f); });

    const sim::Player& player = world.get<sim::Player>();
    const float vehicle_speed = player.vehicle() == sim::Vehicle::Car ? std::fabs(world.get<sim::Car>().speed_mps())
                                                                      : std::fabs(world.get<sim::Boat>().speed_mps());
    tell(wind_, [level = 0.25f + std::min(0.75f, vehicle_speed / 30.0f) + 0.3f * rain](NoiseBed& v) { v.set(level); });
    // The sea is heard near the water: quieter high above it.
    const float height = listener.position.y - world.level().sea_level_m;
    tell(sea_, [level = std::clamp(1.2f - height / 25.0f, 0.2f, 1.0f)](NoiseBed& v) { v.set(level); });

    // Raindrops reaching the windshield, each a tick on the glass.
    const sim::TickReport& report = world.report();
    if (report.glass_drops > 0) {
        const sim::Car& car = world.get<sim::Car>();
        tell(glass_, [n = int(report.glass_drops),
                      place = at(car.position() + car.pose().forward_flat() * 0.9f + glm::vec3(0.0f, 1.2f, 0.0f), 1.5f,
                                 false)](GlassDropsVoice& v) {
            v.land(n, kTickFrames, 0.06f);
            v.place = place;
        });
    }
}

void Soundscape::wipers(const sim::World& world) {
    const sim::RainSim* rain = world.find<sim::RainSim>();
    if (!rain) return;
    const sim::WiperBlade& blade = rain->blades()[0];
    const float angle = blade.angle_rad();
    const float speed = first_tick_ ? 0.0f : std::fabs(angle - blade_angle_) / kTick_s;
    const float turning = blade.turning();
    // What the rubber meets: the water the blades push along (the drops they touched,
    // RainSim's particles), not the drops beyond the sweep, which never dry off in the sim.
    float pushed_mg = 0.0f;
    for (const sim::WaterParticle& p : rain->particles())
        if (!p.dead) pushed_mg += p.mass_mg;
    // Over about a sweep: between sweeps the blades push next to nothing, wet or dry.
    blade_water_mg_ += (pushed_mg - blade_water_mg_) * (kTick_s / kBladeWaterTau_s);
    const float wetness = 1.0f - std::exp(-blade_water_mg_ / kWetBlades_mg);
    state_.pushed_mg = pushed_mg;
    const float blade_speed = std::min(1.0f, speed / kFastestBlade_radps);
    state_.glass_wetness = wetness;
    state_.squeak = WipersVoice::squeak_for(blade_speed, wetness);
    const sim::Car& car = world.get<sim::Car>();
    const glm::vec3 glass = car.position() + car.pose().forward_flat() * 0.9f + glm::vec3(0.0f, 1.1f, 0.0f);
    tell(wipers_, [blade_speed, wetness, running = !rain->motor().parked() || speed > 0.0f,
                   place = at(glass, 1.5f, false)](WipersVoice& v) {
        v.set(blade_speed, wetness, running);
        v.place = place;
    });
    // A thunk where the blade reverses (or stops at rest).
    if (!first_tick_ && blade_turning_ != 0.0f && turning != blade_turning_) {
        StrikeSound thunk;
        thunk.modes[0] = {140.0f, 0.05f, 0.35f};
        thunk.modes[1] = {520.0f, 0.02f, 0.15f};
        thunk.noise_amplitude = 0.4f;
        thunk.noise_decay_s = 0.006f;
        thunk.noise_hz = 1500.0f;
        thunk.seed = next_seed();
        strike(thunk, at(glass, 1.5f, false));
        ++state_.events;
    }
    blade_angle_ = angle;
    blade_turning_ = turning;
}

void Soundscape::shots(const sim::World& world) {
    const sim::Weapon* weapon = world.find<sim::Weapon>();
    if (!weapon) return;
    const sim::WeaponParams& p = weapon->params();
    std::map<uint64_t, ShotHumVoice*> alive;
    for (const sim::Shot& s : weapon->shots()) {
        const uint64_t key = shot_key(s);
        const float t = float(s.age_ticks) * kTick_s;
        float fade = std::clamp((p.life_s - t) / p.fade_s, 0.0f, 1.0f);
        if (s.hit()) fade = std::min(fade, std::clamp(1.0f - float(s.age_ticks - s.hit_age_ticks) * kTick_s / p.fade_s, 0.0f, 1.0f));
        const sim::EnergySegment& head = s.segments.back();
        const float growth = std::clamp(t / p.growth_s, 0.0f, 1.0f), sway = std::sin(s.phase + 7.0f * t);
        const Placement place = at(head.start + head.direction * head.length_m, 6.0f);
        auto found = shot_voices_.find(key);
        if (found != shot_voices_.end()) {
            tell(*found->second, [growth, fade, sway, place](ShotHumVoice& v) {
                v.set(growth, fade, sway);
                v.place = place;
            });
            alive.emplace(key, found->second);
            shot_voices_.erase(found);
        } else {
            // Not in the mix yet: set here, then handed over.
            auto v = std::make_unique<ShotHumVoice>(next_seed());
            v->set(growth, fade, sway);
            v->place = place;
            alive.emplace(key, v.get());
            changes_.play(std::move(v));
        }
    }
    // Shots gone since last tick fade out, and the mixer drops them.
    for (auto& [key, v] : shot_voices_) tell(*v, [](ShotHumVoice& hum) { hum.release(); });
    shot_voices_ = std::move(alive);
}

void Soundscape::tank(const sim::World& world) {
    const sim::FluidTank* tank = world.find<sim::FluidTank>();
    if (!tank) return;
    const glm::vec3 size = tank->inner_size();
    const glm::vec3 centre = glm::vec3(tank->tank_to_world() * glm::vec4(0.5f * size, 1.0f));
    // The liquid sloshing: a watery band by its particles' mean speed (asleep: still).
    float speed = 0.0f;
    if (!tank->asleep()) {
        const std::vector<glm::vec3>& v = tank->fluid().velocities();
        for (const glm::vec3& u : v) speed += std::sqrt(glm::dot(u, u));
        speed /= float(std::max<size_t>(v.size(), 1));
    }
    tell(slosh_, [level = std::min(1.0f, speed / 0.8f), place = at(centre, 3.0f)](NoiseBed& v) {
        v.set(level);
        v.place = place;
    });
    // Something dropped in: a small splash inside and the glass knocked.
    const int inside = tank->objects_inside();
    if (inside > tank_objects_) {
        play_splash(changes_, SplashCause{1.0f, 4.0f, 0.15f, false}, centre, next_seed(), 0);
        StrikeSound glass;
        glass.modes[0] = {620.0f, 0.05f, 0.25f};
        glass.modes[1] = {1630.0f, 0.03f, 0.12f};
        glass.seed = next_seed();
        strike(glass, at(centre, 3.0f));
        ++state_.events;
    }
    tank_objects_ = inside;
}

void Soundscape::hull(const sim::World& world) {
    // The water slapping the hull: at each of the boat's hull points, how high the sea
    // (the wave grid, as the boat's buoyancy reads it) stands over the hull. When it
    // rises against the hull fast (a wave arriving, the hull dropping onto one, the boat
    // running into one) the water slaps there, by how fast it rose.
    const sim::WaterSim* water = world.find<sim::WaterSim>();
    if (!water) return;
    const sim::Boat& boat = world.get<sim::Boat>();
    const sim::Pose& pose = boat.pose();
    const glm::vec3 fwd = pose.forward_flat(), right = pose.right_flat();
    const float sp = std::sin(pose.pitch_rad), sr = std::sin(pose.roll_rad);
    state_.hull_slaps = 0;
    state_.slap_energy = 0.0f;
    state_.hull_rising = 0.0f;
    for (int i = 0; i < sim::Boat::kHullPoints; ++i) {
        const glm::vec2 hp = boat.hull_point(i);
        const glm::vec3 at_hull = pose.position + fwd * hp.x + right * hp.y;
        const float hull_y = pose.position.y + hp.x * sp - hp.y * sr;
        const float immersion = water->height_at({at_hull.x, at_hull.z}) - hull_y;
        const size_t k = size_t(i);
        const float rising = first_tick_ ? 0.0f : (immersion - immersion_[k]) / kTick_s;
        slap_rest_[k] = std::max(0, slap_rest_[k] - 1);
        state_.hull_rising = std::max(state_.hull_rising, rising);
        if (rising > kSlapRise_mps && rising_[k] <= kSlapRise_mps && slap_rest_[k] == 0) {
            const float hard = std::min(1.0f, rising / kSlapHard_mps);
            StrikeSound slap;
            slap.noise_amplitude = 0.9f * hard;
            slap.noise_decay_s = 0.04f;
            slap.noise_hz = 600.0f;
            slap.modes[0] = {hp.x > 0.0f ? 95.0f : 120.0f, 0.07f, 0.5f * hard};  // the hull's planking, the bow's deeper
            slap.seed = next_seed();
            strike(slap, at(glm::vec3(at_hull.x, hull_y, at_hull.z), 5.0f));
            slap_rest_[k] = 20;  // one slap per wave, not one per tick of its rise
            ++state_.hull_slaps;
            state_.slap_energy += hard * hard;
            ++state_.events;
        }
        immersion_[k] = immersion;
        rising_[k] = rising;
    }
}

void Soundscape::events(const sim::World& world) {
    const sim::TickReport& report = world.report();
    for (const sim::ShotReport& fired : report.shots_fired) {
        // The discharge: a short electric snap at the muzzle (the hum's charge follows).
        StrikeSound snap;
        snap.noise_amplitude = 2.2f;
        snap.noise_decay_s = 0.015f;
        snap.noise_hz = 3000.0f;
        snap.noise_q = 0.9f;
        snap.modes[0] = {240.0f, 0.08f, 0.4f};
        snap.seed = next_seed();
        strike(snap, at(fired.position, 6.0f));
        ++state_.events;
    }
    for (const sim::ShotReport& hit : report.shot_impacts) {
        // The crack and the boom; a wall rings a little, the water splashes (its entry below).
        StrikeSound crack;
        crack.noise_amplitude = 1.6f;
        crack.noise_decay_s = 0.02f;
        crack.noise_hz = 2200.0f;
        crack.noise_q = 0.5f;
        crack.modes[0] = {55.0f, 0.35f, 0.9f};
        crack.modes[1] = {110.0f, 0.18f, 0.4f};
        if (hit.surface == sim::ImpactSurface::Solid) crack.modes[2] = {780.0f, 0.09f, 0.3f};
        crack.seed = next_seed();
        strike(crack, at(hit.position, 10.0f));
        ++state_.events;
    }
    for (const sim::WaterEntry& e : report.water_entries) {
        const float speed = std::sqrt(glm::dot(e.velocity, e.velocity));
        play_splash(changes_, SplashCause{e.mass_kg, speed, e.radius_m, e.sinks}, e.position, next_seed(), 0);
        ++state_.events;
    }
    for (const sim::ContactReport& c : report.contacts) {
        // A scrape touches every tick: only a new knock, or a much harder one, thuds.
        const float mass = c.body == sim::ContactBody::Car ? 1300.0f : 1500.0f;
        const float dv = c.impulse_ns / mass;
        if (dv < 0.4f || (world.tick() < last_thud_tick_ + 8 && dv < 2.0f)) continue;
        last_thud_tick_ = world.tick();
        const float hard = std::clamp(std::log10(1.0f + dv) / 1.2f, 0.1f, 1.0f);
        StrikeSound thud;
        thud.modes[0] = {62.0f, 0.14f, 0.9f * hard};
        thud.modes[1] = {150.0f, 0.07f, 0.5f * hard};
        thud.modes[2] = {c.body == sim::ContactBody::Car ? 430.0f : 260.0f, 0.04f, 0.25f * hard};
        thud.noise_amplitude = 0.8f * hard;
        thud.noise_decay_s = 0.015f;
        thud.noise_hz = 900.0f;
        thud.seed = next_seed();
        strike(thud, at(c.position, 5.0f));
        ++state_.events;
    }
    for (const sim::GateReport& g : report.gates) {
        changes_.play(std::make_unique<CueVoice>(g.lap_finished ? CueKind::Lap : CueKind::Gate, 0));
        ++state_.events;
    }
    for (size_t i = 0; i < report.targets_hit.size(); ++i) {
        changes_.play(std::make_unique<CueVoice>(CueKind::Target, 0));
        ++state_.events;
    }
}

}  // namespace audio
