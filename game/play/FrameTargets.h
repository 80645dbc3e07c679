#pragma once
// The frame's targets on a two-core llvmpipe machine, in trivial fills of the output
// (game/bench/TrivialFill.h) so that they hold from host to host: what the resolution
// controller aims at on auto (auto_frame_budget_ms) and what `bench --only play` judges.

namespace game {

inline constexpr double kAutoMeanFills = 15.0;    // auto's mean frame: 30 fps where a fill takes 2.2 ms
inline constexpr double kAutoP95Fills = 22.0;     // auto's 95th percentile frame
inline constexpr double kAutoOutputFills = 3.0;   // what auto draws at the output's size (upscale, UI)
inline constexpr double kAutoMinMeanScale = 0.5;  // auto's time-weighted render scale, at least
inline constexpr double kHighMeanFills = 40.0;    // high's (native) mean frame
inline constexpr double kOpaqueHalfScaleShare = 0.4;  // the opaque pass at scale 0.5, of its cost at 1

}  // namespace game
