#pragma once
// How each deposit looks (docs/effects/dust.md, "Deliberate deviations and why"): the
// same fibre machinery with other fibre statistics, colour and height for dust, sand
// and mould.
#include "effects/dust/FibreVolume.h"
#include "sim/dust/DustDesc.h"

#include <glm/vec3.hpp>

namespace effects {

struct DustLook {
    glm::vec3 colour{0.5f};      // linear albedo of the top of the deposit
    glm::vec3 deep_colour{0.2f}; // at the bottom layer (self-shadowed)
    float height_m = 0.02f;      // shell stack height at amount 1
    float tile_m = 0.3f;         // world size of one fibre texture tile
    float bumpiness = 0.8f;      // luminance clipping depth (0: flat dust surface)
    FibreGrowth growth;
};

DustLook dust_look(sim::DustKind kind);

}  // namespace effects
