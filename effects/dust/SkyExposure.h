#pragma once
// How much of the sky each dusty vertex sees, in [0, 1]: the dust sources' shadow maps
// (sim::SourceDepthMap) turned to the sky. Five maps from far above each dusty prop
// (one overhead, four around at 45 degrees) of every static prop in the scene, so the
// warehouse roof and walls keep the sky's light off the dust inside as the props
// around it keep dust off. Computed once: the scene does not move.
#include <vector>

#include "effects/scene/SceneDesc.h"
#include "sim/dust/DustSurface.h"

namespace effects {

// Indexed like surface.positions(); cosine-weighted over the directions above each
// vertex's surface (0 where none is).
std::vector<float> sky_exposure(const sim::DustSurface& surface, const SceneDesc& scene);

}  // namespace effects
