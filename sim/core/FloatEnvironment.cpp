#include "sim/core/FloatEnvironment.h"

#include <cfenv>
#include <cstdint>

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

namespace sim {

std::string float_environment_problem() {
    std::string problem;
    auto add = [&](const std::string& what) { problem += (problem.empty() ? "" : "; ") + what; };
    if (std::fegetround() != FE_TONEAREST) add("the rounding mode is not round-to-nearest (fegetround)");
#if defined(__SSE__) || defined(__x86_64__)
    // SSE arithmetic has its own rounding and flush controls, apart from the x87 ones
    // fegetround reads.
    const unsigned csr = _mm_getcsr();
    if ((csr & 0x6000u) != 0) add("the SSE rounding mode is not round-to-nearest (MXCSR.RC)");
    if (csr & 0x8000u) add("subnormal results are flushed to zero (MXCSR.FTZ)");
    if (csr & 0x0040u) add("subnormal inputs are read as zero (MXCSR.DAZ)");
#elif defined(__aarch64__)
    uint64_t fpcr = 0;
    asm volatile("mrs %0, fpcr" : "=r"(fpcr));
    if (fpcr & (uint64_t(1) << 24)) add("subnormal numbers are flushed to zero (FPCR.FZ)");
    if (fpcr & (uint64_t(3) << 22)) add("the rounding mode is not round-to-nearest (FPCR.RMode)");
#endif
    return problem;
}

void require_float_environment() {
    const std::string problem = float_environment_problem();
    if (!problem.empty())
        throw FloatEnvironmentError("the sim cannot run in this thread's floating-point environment: " + problem +
                                    ". Its results, and every replay's hashes, are defined with round-to-nearest "
                                    "and subnormals kept; something in this process changed that (a library built "
                                    "with -ffast-math sets FTZ/DAZ when it loads).");
}

}  // namespace sim
