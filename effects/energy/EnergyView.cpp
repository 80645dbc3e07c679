#include "effects/energy/EnergyView.h"

#include <algorithm>

#include "sim/weapon/Weapon.h"

namespace effects {

void gather_energy_view(const sim::World& world, EnergyView& view) {
    view.segments.clear();
    view.lights.clear();
    const sim::Weapon* weapon = world.find<sim::Weapon>();
    if (!weapon) return;
    for (const sim::Shot& shot : weapon->shots()) {
        const sim::EnergySegment& first = shot.segments.front();
        const sim::EnergySegment& last = shot.segments.back();
        if (first.beam_strength <= 0.0f && first.sphere_strength <= 0.0f) continue;  // faded out
        view.segments.insert(view.segments.end(), shot.segments.begin(), shot.segments.end());
        view.lights.push_back({first.start, last.start + last.direction * last.length_m, first.beam_strength});
    }
}

void beam_line_lights(const EnergyView& view, const BeamLighting& lighting, std::vector<LineLight>& lights) {
    lights.clear();
    const size_t n = std::min(view.lights.size(), kMaxLineLights);
    for (size_t i = 0; i < n; ++i) {
        const EnergyBeamLight& b = view.lights[i];
        lights.push_back({b.tail, b.head, lighting.reach_m, lighting.intensity_per_strength * b.strength,
                          glm::vec3(0.45f, 0.7f, 1.0f)});
    }
}

}  // namespace effects
