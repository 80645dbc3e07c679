#pragma once
// Where dust settles and how much (seed §3, after Hsu & Wong 1995): a Phong-like lobe
// about the up direction times the exposure to the dust sources around the prop, the
// exposure read from each source's shadow map (the one overhead weighing double). Computed when a prop is placed.
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/dust/DustDesc.h"
#include "sim/dust/DustSurface.h"

namespace sim {

inline constexpr int kSourceMapSize = 160;

// The sources around a prop: one straight above, the others spread evenly around it
// at the given elevation, all `source_distance` bounding radii from its centre.
std::vector<glm::vec3> place_dust_sources(const DustPropRange& prop, const DustDesc& desc);

// How readily a surface with unit normal n holds this deposit, in [0, 1]: dust mostly
// on tops and thinly on slopes, sand only below its angle of repose, mould also on
// walls; never on faces pointing down.
float dust_lobe(DustKind kind, glm::vec3 n);

// Amounts for the vertices of surface.props()[prop] (written to amounts, indexed like
// the surface's vertices), occluded by every triangle in `occluders` (the level's
// dusty props). Returns the sources it used.
std::vector<glm::vec3> accumulate_dust(const DustSurface& surface, size_t prop,
                                       const std::vector<DustyPropDesc>& occluders, const DustDesc& desc,
                                       std::span<float> amounts);

}  // namespace sim
