#pragma once
// A drop surface read back from the GPU, for the tests and the bench that hold the 2D
// path to the 3D reference.
#include <vector>

#include "effects/gl/Texture.h"
#include "effects/rain/MetaballReference.h"

namespace effects {

// `surface` laid out as DropHeightMap::surface() (ReferenceHeightMap's is too: rg the
// normal's u and v, b the height in mm, a 1 on water), as one sample per texel, rows
// from the bottom: the normal's z follows from u and v, and the height is 0 where a
// is not 1. Waits for the GPU.
std::vector<SurfaceSample> read_surface(const gl::Texture& surface);

}  // namespace effects
