#pragma once
// Cost and quality of the windshield rain: the rain sim per tick with 5,000 drops and
// two wipers, the height-map pipeline per frame at 1024x512, and the seed's fast 2D
// metaballs against a slow 3D metaball reference (time ratio, normal angle error).
// Needs a current GL context.
#include "game/bench/BenchReport.h"

namespace game {

// Adds the "rain" group's cases; `quick` runs fewer ticks and frames.
void bench_rain(BenchReport& report, bool quick);

}  // namespace game
