#pragma once
// Seeking in a replay being watched (docs/REPLAYS.md, "Seeking"): a ten-minute replay
// recorded at bench time from a generated script (the boat lapping the harbour with
// stones and shots: busy water), its keyframes made by one pass to the end, then seeks
// to random ticks and single ticks back, and the keyframes' memory.
#include "game/bench/BenchReport.h"

namespace game {

void bench_replay_seek(BenchReport& report, bool quick);

}  // namespace game
