#pragma once
#include "effects/scene/SceneDesc.h"
#include "sim/world/Terrain.h"

namespace effects {

// The ground as a height-field mesh sampled from the sim's terrain, with rows on the
// quay edge so the drop to the sea bed stays sharp. Colours come from the shader.
Model make_terrain_model(const sim::Terrain& terrain, float spacing_m);

// A large flat quad at sea level reaching the horizon.
Model make_sea_model(float sea_level_m, float half_extent_m);

}  // namespace effects
