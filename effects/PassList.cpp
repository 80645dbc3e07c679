// The frame, in order. An effect adds its pass here, after what it reads.
#include "effects/Renderer.h"
#include "effects/energy/EnergyLightPass.h"
#include "effects/energy/EnergyPass.h"
#include "effects/rain/RainPass.h"
#include "effects/rain/RainStreakPass.h"
#include "effects/fluid/FluidPass.h"
#include "effects/dust/DustPass.h"
#include "effects/scene/EnvironmentPass.h"
#include "effects/scene/FxaaPass.h"
#include "effects/scene/MirrorPass.h"
#include "effects/scene/OpaquePass.h"
#include "effects/scene/SceneCopyPass.h"
#include "effects/scene/ShadowPass.h"
#include "effects/scene/SkyOcclusionPass.h"
#include "effects/scene/TonemapPass.h"
#include "effects/scene/UpscalePass.h"
#include "effects/water/WaterPass.h"

namespace effects {

std::vector<std::unique_ptr<Pass>> make_pass_list() {
    std::vector<std::unique_ptr<Pass>> passes;
    passes.push_back(std::make_unique<EnvironmentPass>());
    passes.push_back(std::make_unique<ShadowPass>());
    passes.push_back(std::make_unique<SkyOcclusionPass>());  // once: the props stay put
    passes.push_back(std::make_unique<EnergyLightPass>());  // before anything is lit
    passes.push_back(std::make_unique<OpaquePass>());
    passes.push_back(std::make_unique<MirrorPass>());  // the view behind, on the mirror's glass
    passes.push_back(std::make_unique<DustPass>());  // shells over the opaque dusty props
    passes.push_back(std::make_unique<SceneCopyPass>());
    passes.push_back(std::make_unique<WaterPass>());
    passes.push_back(std::make_unique<FluidPass>());
    passes.push_back(std::make_unique<EnergyPass>());  // additive, stops at the water's depth too
    passes.push_back(std::make_unique<RainStreakPass>());  // under the windshield
    passes.push_back(std::make_unique<RainPass>());  // refracts everything before it
    passes.push_back(std::make_unique<TonemapPass>());
    passes.push_back(std::make_unique<FxaaPass>());  // at the scene's size: before the upscale, fewer pixels
    passes.push_back(std::make_unique<UpscalePass>());  // to the output's size; the HUD goes on after
    return passes;
}

}  // namespace effects
