#pragma once
#include "game/bench/BenchReport.h"

namespace game {

// The timedemo of every bundled replay (--quick: harbour_drive only) at 1280x720 for
// each quality, headless in the current GL context.
void bench_play(BenchReport& report, bool quick);

}  // namespace game
