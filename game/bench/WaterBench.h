#pragma once
// Cost of the harbour water (sim/water): the wave grid step against a plain copy of
// its arrays, splash sheets with 10k spray droplets, and the whole water subsystem.
#include "game/bench/BenchReport.h"

namespace game {

// Adds the "water" group's cases; `quick` runs fewer ticks.
void bench_water(BenchReport& report, bool quick);

}  // namespace game
