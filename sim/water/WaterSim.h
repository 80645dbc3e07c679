#pragma once
// The harbour water of seed 003 (Sasano 2004; docs/effects/water.md): a wave-equation grid
// over the harbour, splash sheets that rise from it where things hit the water, spray
// particles, and the coupling to the boat, thrown objects and rain. It is also the
// sea surface that floating bodies ride (Subsystem::sea_surface).
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/core/Rng.h"
#include "sim/water/SplashSheet.h"
#include "sim/water/SprayParticles.h"
#include "sim/water/WaveGrid.h"
#include "sim/world/LevelDesc.h"
#include "sim/world/SeaSurface.h"
#include "sim/world/DescribedSubsystem.h"

namespace sim {

class Boat;
class Weather;
struct WaterEntry;

struct WaterParams {
    WaveGridParams grid;          // placed over the harbour by the level
    SplashSheetParams sheet;
    SprayParams spray;
    int max_sheets = 6;           // splash sheets alive at once (oldest reused)
    float boat_wake_strength = 1.0f;
    float rain_dimple_strength = 1.0f;

    float land_clearance_m = 0.2f;       // cells whose ground is above sea level minus this are land
    float impact_push_scale = 1.0f;      // ring-wave push: this times the displaced volume
    // A sinking object's second splash waits for the crater to refill: at least the
    // minimum delay and the centre back within a quarter of its dip, at most the maximum.
    float second_splash_min_s = 0.25f;
    float second_splash_max_s = 0.4f;
    float spray_per_momentum = 0.35f;    // droplets per kg m/s of impact momentum
    int max_spray_per_impact = 600;
    float bow_spray_min_speed_mps = 2.0f;  // forward speed from which the bow throws spray
    float bow_spray_mass_kg = 90.0f;     // the M of the seed's rule for the moving bow
    float bow_spray_per_m = 12.0f;       // droplets per metre run at the bow
    float rain_dimples_per_s = 1200.0f;  // over the whole grid at rain intensity 1
};

// A splash started this tick (for sounds, tests, effects that want the moment).
struct SplashEvent {
    enum class Kind : uint8_t { First, Second };
    Kind kind = Kind::First;
    glm::vec3 position{0.0f};
    float launch_speed_mps = 0.0f;  // speed at alpha = 1
    int sheet = 0;                  // index into WaterSim::sheets()
};

class WaterSim final : public DescribedSubsystem<WaterSim>, public SeaSurface {
public:
    // The grid's land mask comes from the level's terrain. Throws std::invalid_argument
    // naming the bound for unstable or absurd parameters.
    WaterSim(const WaterParams& params, const LevelDesc& level, uint64_t seed);

    static constexpr std::string_view kName = "water";
    std::string_view name() const override { return kName; }
    void connect(const SubsystemLinks& links) override;
    const SeaSurface* sea_surface() const override { return this; }
    void step(StepContext& ctx) override;
    template <class Archive> void describe(Archive& ar) {
        ar.rng_with_stream(rng_);
        for (SheetSlot& s : slots_) ar.fields(s);  // max_sheets of them
        ar.nested(grid_);
        for (SplashSheet& s : sheets_) ar.nested(s);
        ar.nested(spray_);
        ar.unhashed(splashes_);  // this tick's, for sounds and effects
    }
    float height_at(glm::vec2 xz) const override;  // sea level + wave height

    const WaveGrid& grid() const { return grid_; }
    const std::vector<SplashSheet>& sheets() const { return sheets_; }  // inactive ones have active() false
    const SprayParticles& spray() const { return spray_; }
    float sea_level() const { return sea_level_m_; }
    const WaterParams& params() const { return params_; }
    const std::vector<SplashEvent>& splashes() const { return splashes_; }  // started this tick
    // The sheet riding ahead of the boat's bow, or -1 when the boat is slow.
    int bow_sheet() const;
    // Pushes the surface from outside (a blast, a scripted surge): positive depth pushes
    // down, a raised cosine of the given radius; it then spreads as waves.
    void disturb(glm::vec2 xz, float radius_m, float depth_m) { grid_.push(xz, radius_m, depth_m); }

private:
    struct SheetSlot {
        uint64_t started_tick = 0;
        bool bow = false;             // attached ahead of the boat's bow
        bool second_pending = false;  // a sinking object's crater is refilling
        uint32_t ticks_since_impact = 0;
        float object_radius_m = 0.0f;
        float momentum_kgmps = 0.0f;
        float dip_m = 0.0f;           // wave height at the entry right after the push
        glm::vec3 impact{0.0f};

        template <class Archive> void describe(Archive& ar) {
            ar.u64(started_tick);
            ar.flags(bow, second_pending);
            ar.u32(ticks_since_impact);
            ar.f32(object_radius_m);
            ar.f32(momentum_kgmps);
            ar.f32(dip_m);
            ar.vec(impact);
        }
    };

    int take_sheet(uint64_t tick);  // an idle sheet, else the oldest one not on the bow
    void rain(float intensity);
    void second_splashes();
    void impact(const WaterEntry& entry, uint64_t tick);
    void boat(const Boat& boat, uint64_t tick);

    WaterParams params_;
    float sea_level_m_;
    float dt_;
    WaveGrid grid_;
    std::vector<SplashSheet> sheets_;
    std::vector<SheetSlot> slots_;
    SprayParticles spray_;
    Rng rng_;
    std::vector<SplashEvent> splashes_;
    std::vector<Ripple> ripples_;  // scratch: where sheet vertices and droplets fell back

    // Connected at assembly (connect); nullptr where the world has none.
    const Weather* weather_ = nullptr;
    const Boat* boat_ = nullptr;
};

}  // namespace sim
