#include "sim/water/WaveRow.h"

namespace sim {

namespace {

[[gnu::always_inline]] inline void row_loop(const float* __restrict up, const float* __restrict r,
                                            const float* __restrict dn, float* __restrict o, size_t n,
                                            WaveRowWeights w) {
    const float c = w.c, w3 = w.w3, w4 = w.w4, keep = w.keep;
    o[0] = flushed(c * (r[1] + (up[0] + dn[0])) + w3 * r[0] - keep * o[0]);
    for (size_t i = 1; i + 1 < n; ++i)
        o[i] = flushed(c * ((r[i - 1] + r[i + 1]) + (up[i] + dn[i])) + w4 * r[i] - keep * o[i]);
    o[n - 1] = flushed(c * (r[n - 2] + (up[n - 1] + dn[n - 1])) + w3 * r[n - 1] - keep * o[n - 1]);
}

void row_baseline(const float* up, const float* r, const float* dn, float* o, size_t n, WaveRowWeights w) {
    row_loop(up, r, dn, o, n, w);
}

#if defined(__x86_64__) || defined(__i386__)
[[gnu::target("avx2")]] void row_avx2(const float* up, const float* r, const float* dn, float* o, size_t n,
                                     WaveRowWeights w) {
    row_loop(up, r, dn, o, n, w);
}
#endif

}  // namespace

bool wave_row_has_avx2() {
#if defined(__x86_64__) || defined(__i386__)
    static const bool has = __builtin_cpu_supports("avx2");
    return has;
#else
    return false;  // another CPU: the baseline code only
#endif
}

void step_wave_row(const float* up, const float* row, const float* down, float* out, size_t n, WaveRowWeights w,
                   WaveRowCode code) {
#if defined(__x86_64__) || defined(__i386__)
    if (code == WaveRowCode::kAvx2) return row_avx2(up, row, down, out, n, w);
#endif
    (void)code;
    row_baseline(up, row, down, out, n, w);
}

}  // namespace sim
