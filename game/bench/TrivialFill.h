#pragma once
// The floor any full-screen pass stands on: one triangle covering a width x height
// RGBA8 target with a constant colour (no blending, no depth), timed with glFinish and
// the wall clock. Frame times divided by it compare across machines.
namespace game {

// Median of `repeats` fills, in milliseconds. Needs a current GL context; leaves the
// default framebuffer bound.
double trivial_fill_ms(int width, int height, int repeats = 101);

}  // namespace game
