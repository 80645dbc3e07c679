#pragma once
// Cost and accuracy of the energy wave (effects/energy, docs/effects/energy.md
// "Benchmarks"): closed form against ray marching (time, error against a quadrature,
// samples marching needs to match), 1/10/100 segments at three sizes with per-tile
// culling, and a full-screen energy pass against a trivial fill of the same size.
#include "game/bench/BenchReport.h"

namespace game {

// Adds the "energy" group's cases; needs a current GL context. `quick` times fewer frames.
void bench_energy(BenchReport& report, bool quick);

}  // namespace game
