// Built only to prove that tests/sim_symbols.cmake notices a libm call (CTest's
// sim.libm_symbols.noticed): sinf and expf here must be reported.
#include <cmath>

float calls_libm_sin(float x) { return std::sin(x); }
float calls_libm_exp(float x) { return std::exp(x); }
float calls_only_sqrt(float x) { return std::sqrt(x); }
