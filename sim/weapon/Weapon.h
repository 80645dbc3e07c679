#pragma once
// The energy weapon as the sim sees it: shots made of segments that grow from a ball
// into a beam, travel, sway and fade, all from the shot's start, direction and age.
// A shot whose head reaches the water or the ground stops there and drains into the
// impact point; a water impact is reported in World::events() for the water to splash.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "sim/core/Rng.h"
#include "sim/weapon/EnergySegment.h"
#include "sim/world/DescribedSubsystem.h"
#include "sim/world/TickReport.h"
#include "sim/world/WorldEvents.h"

namespace sim {

class Player;
class Car;
class Boat;

struct Shot {
    static constexpr int kSegments = 4;
    glm::vec3 origin{0.0f};
    glm::vec3 direction{1.0f, 0.0f, 0.0f};
    float phase = 0.0f;  // random per shot: how it sways
    uint32_t age_ticks = 0;
    uint32_t hit_age_ticks = 0;  // age when the head hit water, ground or a solid; 0 while in flight
    float hit_distance_m = 0.0f;  // from the origin along the direction, once hit
    std::array<EnergySegment, kSegments> segments{};
    bool hit() const { return hit_age_ticks != 0; }

    template <class Archive> void describe(Archive& ar) {
        ar.vec(origin);
        ar.vec(direction);
        ar.f32(phase);
        ar.u32(age_ticks);
        ar.u32(hit_age_ticks);
        ar.f32(hit_distance_m);
        for (EnergySegment& s : segments) ar.fields(s);
    }
};

struct WeaponParams {
    float speed_mps = 45.0f;
    float max_length_m = 14.0f;    // beam length once grown
    float growth_s = 0.6f;         // ball to full beam
    float life_s = 2.5f;
    float fade_s = 0.6f;           // at the end of its life, or after a hit
    float strength = 0.12f;        // a = b of every segment at full brightness
    float radius_m = 1.1f;         // field cut-off around each segment
    float sway_m = 0.35f;
    float dip_rad = 0.05f;         // fired this far below the vehicle's heading (about 3 degrees)
    float muzzle_height_m = 1.4f;  // above the vehicle's origin
    float muzzle_ahead_m = 3.0f;
    // What the water feels on impact (WaterEntry): a light, fast body that floats.
    float impact_radius_m = 0.45f;
    float impact_mass_kg = 40.0f;
};

class Weapon final : public DescribedSubsystem<Weapon> {
public:
    static constexpr size_t kMaxShots = 8;

    explicit Weapon(uint64_t seed, WeaponParams params = {});

    static constexpr std::string_view kName = "weapon";
    std::string_view name() const override { return kName; }
    void connect(const SubsystemLinks& links) override;
    void step(StepContext& ctx) override;
    template <class Archive> void describe(Archive& ar) {
        ar.rng(rng_);
        ar.size32(shots_);
        for (Shot& s : shots_) ar.fields(s);
    }

    void fire(glm::vec3 origin, glm::vec3 direction);
    const std::vector<Shot>& shots() const { return shots_; }
    const WeaponParams& params() const { return p_; }

private:
    // Ages a shot by one tick, detects its impact and lays out its segments.
    // Its impact, if any, goes to `impacts` (the tick report).
    void advance(Shot& s, const World& world, float dt, std::vector<WaterEntry>& water_entries,
                 std::vector<ShotReport>& impacts) const;
    void shape(Shot& s, float dt) const;

    WeaponParams p_;
    Rng rng_;
    std::vector<Shot> shots_;

    // Connected at assembly (connect).
    const Player* player_ = nullptr;
    const Car* car_ = nullptr;
    const Boat* boat_ = nullptr;
};

}  // namespace sim
