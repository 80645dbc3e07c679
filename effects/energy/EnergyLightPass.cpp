#include "effects/energy/EnergyLightPass.h"

namespace effects {

void EnergyLightPass::register_params(ParamRegistry& params) {
    params.add("energy", "light per strength", &intensity_per_strength_, 0.0f, 400.0f);
    params.add("energy", "light reach m", &reach_m_, 1.0f, 40.0f);
}

std::vector<LineLight> EnergyLightPass::lights(const EnergyView& view) const {
    std::vector<LineLight> out;
    for (const EnergyBeamLight& b : view.lights)
        out.push_back({b.tail, b.head, reach_m_, intensity_per_strength_ * b.strength, glm::vec3(0.45f, 0.7f, 1.0f)});
    return out;
}

void EnergyLightPass::render(const FrameContext& frame) {
    frame.scene.lighting.set_line_lights(lights(frame.data.energy));
}

}  // namespace effects
