#pragma once
// The dust texture of seed §2: fibres grown point by point through a volume of
// shell layers. In its jitter parts a fibre draws each step from the direction table
// weighted towards its global direction; with a set probability it bends, and the
// global direction (hence the weights) changes. Many fibres overlaid give each layer
// its texture. Deterministic from the seed; tiles in x and y.
#include <cstdint>
#include <vector>

#include "effects/dust/FibreDirections.h"

namespace effects {

struct FibreGrowth {
    int size = 128;                 // texels per side of a layer
    int layers = 10;                // the seed's 10 shells
    int fibres = 700;
    int steps = 60;                 // points per fibre
    float bend_probability = 0.06f; // per step
    float direction_bias = 3.0f;    // how strongly the global direction steers the jitter
    float climb = 0.25f;            // vertical part of a global direction, at most
    float bottom_heavy = 2.0f;      // start layers ~ u^this: more fibres low down
    uint64_t seed = 1;
};

struct FibreVolume {
    int size = 0, layers = 0;
    // Two bytes per texel, layer-major then rows: fibre coverage (255 on a fibre) and
    // the fibre's rank in [1, 255] (thinner dust keeps only the low ranks).
    std::vector<uint8_t> texels;
    uint8_t coverage(int x, int y, int layer) const { return texels[index(x, y, layer)]; }
    uint8_t rank(int x, int y, int layer) const { return texels[index(x, y, layer) + 1]; }
    size_t index(int x, int y, int layer) const { return ((size_t(layer) * size_t(size) + size_t(y)) * size_t(size) + size_t(x)) * 2; }
};

// Throws std::invalid_argument for an empty direction table or sizes out of range.
FibreVolume grow_fibres(const FibreDirections& directions, const FibreGrowth& growth);

}  // namespace effects
