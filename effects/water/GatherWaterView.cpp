#include "effects/water/WaterView.h"

#include "sim/water/WaterSim.h"
#include "sim/world/World.h"

namespace effects {

void gather_water_view(const sim::World& world, WaterView& out) {
    out.sheets.clear();
    out.spray.clear();
    const sim::WaterSim* water = world.find<sim::WaterSim>();
    if (!water) {
        out.sea_level_m = world.level().sea_level_m;
        out.grid.reset();
        return;
    }
    out.sea_level_m = water->sea_level();
    const sim::WaveGrid& g = water->grid();
    out.grid = WaveHeights{g.size(), g.spacing(), g.origin(), g.heights()};
    for (const sim::SplashSheet& s : water->sheets())
        if (s.active()) out.sheets.push_back({s.size(), s.spacing(), s.positions(), s.airborne(), s.centre_xz()});
    const auto& drops = water->spray().particles();
    out.spray.reserve(drops.size());
    for (const sim::SprayParticle& p : drops) out.spray.push_back({p.position, p.radius_m});
}

}  // namespace effects
