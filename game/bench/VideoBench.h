#pragma once
// The video export's speed (spindrift replay --video): the first seconds of
// replays/harbour_goals.replay exported at 1280x720 and 60 fps with its sound, in
// frames a second, and the share of the wall-clock time spent in the encoder's calls
// (x264 also works in threads of its own, beside the rendering, which that share does
// not see).
#include "game/bench/BenchReport.h"

namespace game {

// Adds the "video" group's cases; needs a current GL context. `quick` exports fewer frames.
void bench_video(BenchReport& report, bool quick);

}  // namespace game
