#pragma once
// The floor any full-screen pass stands on: one triangle covering a width x height
// RGBA8 target with a constant colour (no blending, no depth), timed with glFinish and
// the wall clock. Frame times divided by it compare across machines.
#include <vector>

namespace game {

inline constexpr int kFillsPerSample = 8;
// `repeats` samples in milliseconds (after an untimed round that compiles llvmpipe's
// variant), each the mean of kFillsPerSample fills drawn back to back into as many
// targets, as a frame's passes run. A lone fill timed on its own read 0.4, 0.7 or
// 1.35 ms on one machine from one moment to the next, for reasons not found; eight in a
// row read within a few percent of each other. Needs a current GL context; leaves the
// default framebuffer bound.
std::vector<double> trivial_fill_samples(int width, int height, int repeats);
// The median of `samples`: the upper of the middle two for an even count, 0 for none.
double median_ms(std::vector<double> samples);

}  // namespace game
