#include "effects/rain/RainView.h"

#include "sim/player/Player.h"
#include "sim/rain/GlassSurface.h"
#include "sim/rain/RainSim.h"
#include "sim/vehicle/Car.h"
#include "sim/world/World.h"

namespace effects {

void gather_rain_view(const sim::World& world, RainView& out) {
    out.metaballs.clear();
    out.blades.clear();
    out.film.clear();
    const sim::RainSim* rain = world.find<sim::RainSim>();
    const sim::Player* player = world.find<sim::Player>();
    const sim::Car* car = world.find<sim::Car>();
    out.glass = rain ? &rain->glass() : nullptr;
    out.driver_view = player && car && player->vehicle() == sim::Vehicle::Car && player->view() == sim::ViewMode::Driver;
    if (!rain || !out.driver_view) return;
    out.car_to_world = car->pose().matrix();
    for (const sim::RainDrop& d : rain->drops()) out.metaballs.push_back({d.pos_m, d.radius_m, 0.0f});
    for (const sim::WaterParticle& q : rain->particles())
        out.metaballs.push_back({q.pos_m, sim::RainSim::radius_m(q.mass_mg), 0.0f});
    for (const sim::WiperBlade& b : rain->blades())
        out.blades.push_back({b.params().pivot_m, b.direction(), b.params().inner_m, b.params().outer_m});
    out.wipers_parked = rain->motor().parked();
    const sim::GlassSurface& glass = rain->glass();
    out.film_cols = glass.cols();
    out.film_rows = glass.rows();
    out.film_cell_m = glass.cell_m();
    out.film.resize(size_t(glass.cell_count()));
    for (int c = 0; c < glass.cell_count(); ++c) out.film[size_t(c)] = uint8_t(rain->wetness(c) * 255.0f + 0.5f);
}

}  // namespace effects
