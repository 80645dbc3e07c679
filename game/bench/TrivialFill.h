#pragma once
// The floor any full-screen pass stands on: one triangle covering a width x height
// RGBA8 target with a constant colour (no blending, no depth), timed with glFinish and
// the wall clock. Frame times divided by it compare across machines.
#include <vector>

namespace game {

// `repeats` single fills, each timed on its own, in milliseconds (after one untimed fill
// that compiles llvmpipe's variant). Needs a current GL context; leaves the default
// framebuffer bound.
std::vector<double> trivial_fill_samples(int width, int height, int repeats);
// The median of `samples`: the upper of the middle two for an even count, 0 for none.
double median_ms(std::vector<double> samples);

}  // namespace game
