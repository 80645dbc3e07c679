#pragma once
// The slow reference the seed compares its compressed 2D metaballs with (seed 5.5,
// docs/effects/rain.md "Benchmarks"): the same drops as 3D metaballs, each a field
// N(d) = 1 / (1 + (d/R)^4) of the 3D distance to its centre on the glass, cut off at
// kMetaballReach radii like the splats, and the water surface the iso-surface N = T
// above the glass, found per texel by bisection on the CPU (one thread). A lone drop
// is then exactly a hemisphere of radius R. ReferenceHeightMap does the same on the GPU.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "effects/rain/RainView.h"

namespace effects {

struct SurfaceSample {
    glm::vec3 normal{0.0f, 0.0f, 1.0f};  // in glass coordinates, z out of the glass
    float height_mm = 0.0f;              // 0: dry
};

// Both references bisect the height above the glass from 0 to kMetaballReach times
// the largest radius (no surface can be higher), halving it this many times.
constexpr int kReferenceBisections = 24;
float bisection_ceiling_m(std::span<const RainMetaball> drops);

// Heights and normals over a width x height grid of texels covering glass_size_m,
// sampled at texel centres like the GPU path; row 0 at v = 0.
std::vector<SurfaceSample> reference_surface(std::span<const RainMetaball> drops, glm::vec2 glass_size_m, int width,
                                             int height, float threshold = 0.5f);

// A cluster of overlapping drops of several sizes (merged drops, a trail, a bead):
// the scene the 2D path is compared on. Fills glass_size_m.
std::vector<RainMetaball> merged_drop_scene(glm::vec2& glass_size_m);

// Mean angle in degrees between two surfaces' normals over texels wet in both;
// `wet_both` gets how many there were.
double mean_normal_angle_deg(std::span<const SurfaceSample> a, std::span<const SurfaceSample> b, size_t& wet_both);

}  // namespace effects
