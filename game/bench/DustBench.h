#pragma once
// Cost of the dusty props (seed 004, docs/effects/dust.md "Benchmarks"): the dust
// pass over the warehouse props per frame against the same props drawn without dust,
// fibre texture generation, and the accumulation (shadow maps and amounts) per prop.
#include "game/bench/BenchReport.h"

namespace game {

// The CPU cases: fibre growth and accumulation per prop.
void bench_dust_cpu(BenchReport& report, bool quick);
// Where the GPU cases look from: over the warehouse props from the door, or close to
// the crates, where the dust is drawn with every shell and fin.
enum class DustBenchView { Warehouse, CloseUp };

// The GPU cases at width x height; needs a current GL context.
void bench_dust_render(BenchReport& report, int width, int height, bool quick,
                       DustBenchView where = DustBenchView::Warehouse);

}  // namespace game
