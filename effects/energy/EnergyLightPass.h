#pragma once
// The energy beams as line lights (docs/effects/energy.md, "What is implemented"):
// before the opaque scene is lit, each shot in flight becomes one line light from its
// tail to its head in the scene lighting, so walls, ground and props near it glow.
#include "effects/energy/EnergyView.h"
#include "effects/scene/Pass.h"

namespace effects {

class EnergyLightPass final : public Pass {
public:
    std::string_view name() const override { return "energy_lights"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

    // The line lights these beams make (what render() sets).
    std::vector<LineLight> lights(const EnergyView& view) const;

private:
    float intensity_per_strength_ = 60.0f;  // line-light intensity per unit of segment strength
    float reach_m_ = 9.0f;
};

}  // namespace effects
