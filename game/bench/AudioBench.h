#pragma once
// The sound's cost: synthesis and mixing per 512-frame block (10.7 ms of sound, the
// live output's block) while each bundled replay plays, mean and p99, with the voices
// playing. Thread CPU time of the mixing alone; the sim's ticks are not counted.
#include "game/bench/BenchReport.h"

namespace game {

// Adds the "audio" group's cases; `quick` runs one replay.
void bench_audio(BenchReport& report, bool quick);

}  // namespace game
