#pragma once
// The floating-point environment the sim's results are defined in (docs/DETERMINISM.md):
// rounding to nearest, and subnormal numbers kept, neither flushed to zero as results
// (x86 MXCSR.FTZ, Arm FPCR.FZ) nor read as zero (x86 MXCSR.DAZ). A library built with
// -ffast-math (its crtfastmath.o sets FTZ/DAZ at load), or a caller's fesetround, would
// change the sim's results on this machine alone; the sim refuses to run instead.
#include <stdexcept>
#include <string>

namespace sim {

struct FloatEnvironmentError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What differs from the environment the sim needs on this thread; empty when none.
std::string float_environment_problem();

// Throws FloatEnvironmentError naming what differs. The World checks at every step and
// the JobPool before it starts its workers (threads inherit their creator's environment).
void require_float_environment();

}  // namespace sim
