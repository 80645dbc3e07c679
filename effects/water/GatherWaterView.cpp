#include "effects/water/WaterView.h"

#include "sim/water/WaterSim.h"
#include "sim/world/World.h"

namespace effects {

void gather_water_view(const sim::World& world, WaterView& out) {
    out.sheets.clear();
    out.spray.clear();
    out.tick = int64_t(world.tick());
    out.tick_s = 1.0f / float(sim::kTickRateHz);
    out.restore_generation = world.restore_generation();
    const sim::WaterSim* water = world.find<sim::WaterSim>();
    if (!water) {
        out.sea_level_m = world.level().sea_level_m;
        out.grid.reset();
        return;
    }
    out.sea_level_m = water->sea_level();
    const sim::WaveGrid& g = water->grid();
    out.grid = WaveHeights{g.size(), g.spacing(), g.origin(), g.heights()};
    const int bow = water->bow_sheet();
    for (size_t k = 0; k < water->sheets().size(); ++k) {
        const sim::SplashSheet& s = water->sheets()[k];
        if (s.active())
            out.sheets.push_back({s.size(), s.spacing(), s.positions(), s.airborne(), s.centre_xz(), s.velocities(),
                                  int(k), s.params().gravity_mps2, int(k) == bow});
    }
    const auto& drops = water->spray().particles();
    out.spray.reserve(drops.size());
    for (const sim::SprayParticle& p : drops) out.spray.push_back({p.position, p.radius_m});
}

}  // namespace effects
