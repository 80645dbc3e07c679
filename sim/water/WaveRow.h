#pragma once
// The wave grid's tight loop: one interior row with no land near (WaveGrid.cpp),
//   out[i] = c (left + right + up + down) + w y[i] - keep out[i],  w = w3 at both ends,
// heights below 1e-30 m flushed to 0. It is memory-bound on the baseline x86-64 build
// only where memory is slow; with caches as fast as glibc's AVX2 copy it is the
// arithmetic that counts, so the loop is also compiled for AVX2 and picked at run time.
// Both do the same IEEE operations per cell in the same order (no fused multiply-add):
// the same bits, which tests/wave_grid_test.cpp checks.
#include <cmath>
#include <cstddef>

namespace sim {

// Heights this small are flushed to 0: the scheme's numerical fronts and long damped
// tails would otherwise fill the grid with subnormal floats, which x86 handles ~100x
// slower (and the sim must not change the FPU's flush modes).
constexpr float kWaveFlush_m = 1e-30f;

[[gnu::always_inline]] inline float flushed(float y) { return std::fabs(y) < kWaveFlush_m ? 0.0f : y; }

struct WaveRowWeights {
    float c, w3, w4, keep;
};

enum class WaveRowCode { kBaseline, kAvx2 };

// Whether this processor runs the AVX2 code.
bool wave_row_has_avx2();

// up, row, down: the row and its neighbours' heights; out: the previous heights in,
// the next ones out. n >= 2. kAvx2 only where wave_row_has_avx2().
void step_wave_row(const float* up, const float* row, const float* down, float* out, size_t n, WaveRowWeights w,
                   WaveRowCode code);

}  // namespace sim
