#include "game/bench/RainBench.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "effects/gl/Gl.h"
#include "effects/rain/DropHeightMap.h"
#include "effects/rain/MetaballReference.h"
#include "effects/rain/RainPass.h"
#include "effects/rain/ReferenceHeightMap.h"
#include "effects/rain/SurfaceReadback.h"
#include "game/bench/BenchSupport.h"
#include "game/level/LevelLoader.h"
#include "game/stage/RenderStage.h"
#include "sim/rain/RainSim.h"

namespace game {

namespace {

using Clock = std::chrono::steady_clock;

double cpu_seconds(clockid_t clock) {
    timespec ts{};
    clock_gettime(clock, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}
// This thread's CPU time: what one core spends, whatever else the machine is running.
double thread_cpu_seconds() { return cpu_seconds(CLOCK_THREAD_CPUTIME_ID); }
// The whole process's: with llvmpipe, what its threads spend on the "GPU" path.
double process_cpu_seconds() { return cpu_seconds(CLOCK_PROCESS_CPUTIME_ID); }

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

struct DropMasses {
    float lo_mg, hi_mg;
};

// Tops the glass up to `count` drops (the wipers clear drops and sliding ones run off).
void top_up(sim::RainSim& rain, sim::Rng& rng, int count, DropMasses m) {
    const sim::GlassSurface& g = rain.glass();
    while (int(rain.drops().size()) < count)
        rain.add_drop({rng.unit() * float(g.cols()) * g.cell_m(), rng.unit() * float(g.rows()) * g.cell_m()},
                      rng.range(m.lo_mg, m.hi_mg));
}

// The harbour car's glass with `count` drops on it.
sim::RainSim busy_glass(int count, DropMasses m = {1.0f, 40.0f}) {
    LoadedLevel level = load_level("harbour");
    sim::RainSim rain({}, level.sim.rain.glass_lower, level.sim.rain.glass_upper, 4242);
    sim::Rng rng(77, 1);
    top_up(rain, rng, count, m);
    return rain;
}

// 5,000 drops of `masses` with both wipers on high, the car at speed_mps, topped up
// to 5,000 before every tick (untimed).
void bench_sim(BenchReport& report, int ticks, const std::string& what, DropMasses masses, float speed,
               std::optional<double> target_ms = 1.0) {
    sim::RainSim rain = busy_glass(5000, masses);
    sim::Rng rng(78, 1);
    const sim::RainForces forces = rain.forces_for(speed, {0.0f, 0.0f}, {0.0f, -9.81f, 0.0f});
    double wall = 0.0, cpu = 0.0, particles = 0.0, moving = 0.0;
    for (int t = 0; t < ticks; ++t) {
        top_up(rain, rng, 5000, masses);
        const auto start = Clock::now();
        const double cpu_start = thread_cpu_seconds();
        rain.advance(1.0f, sim::WiperMode::High, speed, forces, 1.0f / 60.0f);
        cpu += thread_cpu_seconds() - cpu_start;
        wall += seconds_since(start);
        particles += double(rain.particles().size());
        for (const sim::RainDrop& d : rain.drops()) moving += d.vel_mps != glm::vec2(0.0f);
    }
    report.add({"rain", "rain sim per tick, 5000 drops " + what + ", two wipers on high (CPU time)", cpu * 1e3 / ticks,
                "ms", target_ms, false,
                "1 thread; wall " + fmt("%.3f", wall * 1e3 / ticks) + " ms; mean " + fmt("%.0f", moving / ticks) +
                    " drops moving, " + fmt("%.0f", particles / ticks) + " wiper particles"});
}

std::vector<effects::RainMetaball> metaballs_of(const sim::RainSim& rain) {
    std::vector<effects::RainMetaball> out;
    for (const sim::RainDrop& d : rain.drops()) out.push_back({d.pos_m, d.radius_m, 0.0f});
    for (const sim::WaterParticle& q : rain.particles()) out.push_back({q.pos_m, sim::RainSim::radius_m(q.mass_mg), 0.0f});
    return out;
}

void bench_height_map(BenchReport& report, int frames) {
    sim::RainSim rain = busy_glass(5000);
    const sim::RainForces forces = rain.forces_for(0.0f, {0.0f, 0.0f}, {0.0f, -9.81f, 0.0f});
    for (int t = 0; t < 60; ++t) rain.advance(1.0f, sim::WiperMode::High, 0.0f, forces, 1.0f / 60.0f);
    const std::vector<effects::RainMetaball> balls = metaballs_of(rain);
    const glm::vec2 size(rain.glass().width_m(), rain.glass().height_m());
    const float scale = effects::RainLook{}.radius_scale;  // as the pass draws them
    effects::DropHeightMap map(1024, 512);
    map.update(balls, size, scale);
    glFinish();
    auto start = Clock::now();
    for (int f = 0; f < frames; ++f) map.update(balls, size, scale);
    glFinish();
    // The frame's part of the map: the windshield takes heights and normals per pixel.
    report.add({"rain", "height map: splat @1024x512", seconds_since(start) * 1e3 / frames, "ms",
                std::nullopt, false, std::to_string(balls.size()) + " metaballs; glFinish around the frames"});
}

struct GpuTimes {
    std::vector<double> wall_s, cpu_s;
};

// Wall time around glFinish, and the process's CPU time (under llvmpipe, the "GPU" work).
template <typename Draw>
void time_gpu(GpuTimes& t, Draw&& draw) {
    glFinish();
    const auto start = Clock::now();
    const double cpu_start = process_cpu_seconds();
    draw();
    glFinish();
    t.wall_s.push_back(seconds_since(start));
    t.cpu_s.push_back(process_cpu_seconds() - cpu_start);
}

// The merged-drop scene repeated over a 1024x512 height map at the texel size of
// tests/rain_render_test.cpp (4 x 4 tiles): per-frame costs such as the draw calls and
// glFinish weigh no more than at the game's resolution. The 2D path and the 3D
// reference on the GPU are timed the same way, alternately so the machine's load falls
// on both alike: a warm-up each, then the median of `runs`. Both shade per texel only
// the tiles where water can be (WetTiles; their CPU binning is in the time), the 2D
// path after splatting every drop. The CPU reference (this thread's CPU time) is the
// exactness oracle the GPU one is checked against.
void bench_reference(BenchReport& report, int runs) {
    glm::vec2 tile;
    const std::vector<effects::RainMetaball> one = effects::merged_drop_scene(tile);
    constexpr int kTiles = 4, w = 1024, h = 512;
    std::vector<effects::RainMetaball> scene;
    for (int j = 0; j < kTiles; ++j)
        for (int i = 0; i < kTiles; ++i)
            for (effects::RainMetaball d : one) {
                d.centre_m += tile * glm::vec2(float(i), float(j));
                scene.push_back(d);
            }
    const glm::vec2 size = tile * float(kTiles);
    effects::DropHeightMap map(w, h);
    effects::ReferenceHeightMap reference(w, h);
    GpuTimes fast_t, gpu_ref_t, warm_up;
    for (int r = 0; r <= runs; ++r) {
        time_gpu(r > 0 ? fast_t : warm_up, [&] {
            map.update(scene, size, 1.0f);
            map.surface();  // heights and normals per texel, as the reference gives them
        });
        time_gpu(r > 0 ? gpu_ref_t : warm_up, [&] { reference.update(scene, size); });
    }
    const std::vector<effects::SurfaceSample> fast = effects::read_surface(map.surface());
    const std::vector<effects::SurfaceSample> gpu_ref = effects::read_surface(reference.surface());
    std::vector<effects::SurfaceSample> cpu_ref;
    std::vector<double> cpu_ref_s;
    for (int r = 0; r <= runs; ++r) {
        const double start = thread_cpu_seconds();
        cpu_ref = effects::reference_surface(scene, size, w, h);
        if (r > 0) cpu_ref_s.push_back(thread_cpu_seconds() - start);
    }
    size_t wet = 0, wet_cpu = 0, wet_refs = 0;
    const double angle = effects::mean_normal_angle_deg(fast, gpu_ref, wet);
    const double angle_cpu = effects::mean_normal_angle_deg(fast, cpu_ref, wet_cpu);
    const double refs_angle = effects::mean_normal_angle_deg(gpu_ref, cpu_ref, wet_refs);
    const double fast_med = median(fast_t.wall_s), gpu_ref_med = median(gpu_ref_t.wall_s), cpu_ref_med = median(cpu_ref_s);
    const std::string res = std::to_string(w) + "x" + std::to_string(h), of = "median of " + std::to_string(runs);
    const std::string cpu_note = "; process CPU ";
    report.add({"rain", "2D metaball path @" + res + " (GPU, wall)", fast_med * 1e3, "ms", std::nullopt, false,
                std::to_string(scene.size()) + " merged drops (" + std::to_string(kTiles * kTiles) +
                    " tiles); splat, then height and normals over the wet tiles; " + of +
                    cpu_note + fmt("%.1f", median(fast_t.cpu_s) * 1e3) + " ms"});
    report.add({"rain", "3D metaball reference @" + res + " (GPU, wall)", gpu_ref_med * 1e3, "ms", std::nullopt, false,
                "iso-surface by bisection over the drops culled per 16x16 texels, then normals, both over the wet "
                "tiles; " + of + cpu_note +
                    fmt("%.1f", median(gpu_ref_t.cpu_s) * 1e3) + " ms; " + fmt("%.3f", refs_angle) +
                    " deg from the CPU reference"});
    report.add({"rain", "3D metaball reference @" + res + " (CPU time)", cpu_ref_med * 1e3, "ms", std::nullopt, false,
                "the same bisection, 1 thread; " + of});
    report.add({"rain", "3D reference (GPU) / 2D path time, both GPU wall", gpu_ref_med / fast_med, "x", 20.0, true});
    report.add({"rain", "3D reference (CPU time) / 2D path (GPU wall) time", cpu_ref_med / fast_med, "x", std::nullopt,
                true, "mixes execution environments"});
    report.add({"rain", "mean normal angle error, 2D vs 3D (GPU)", angle, "deg", 5.0, false,
                std::to_string(wet) + " texels wet in both"});
    report.add({"rain", "mean normal angle error, 2D vs 3D (CPU)", angle_cpu, "deg", std::nullopt, false,
                std::to_string(wet_cpu) + " texels wet in both"});
}

// The whole rain pass in the driver's view of the harbour car, parked in heavy rain
// with the wipers on low: height map, scene copy with mips, windshield.
void bench_pass(BenchReport& report, int width, int height, int frames) {
    RenderStage stage("harbour", {.width = width, .height = height, .environment_size = 64});
    stage.renderer().set_timing(effects::gl::TimingMode::Profile);
    sim::World& world = stage.world();
    for (uint32_t t = 0; t < 300; ++t) {
        sim::TickInput in;
        in.set(sim::Control::Camera, t == 0);
        in.set(sim::Control::RainUp, t == 2 || t == 4 || t == 6 || t == 8);
        in.set(sim::Control::Wipers, t == 100 || t == 102);
        world.step(in);
    }
    stage.draw_as_game();
    double ms = 0.0;
    for (int f = 0; f < frames; ++f) {
        world.step({});
        stage.draw_as_game();
        for (const auto& p : stage.renderer().pass_times())
            if (p.name == "rain") ms += p.ms;
    }
    report.add({"rain", "rain pass in the driver's view @" + std::to_string(width) + "x" + std::to_string(height),
                ms / frames, "ms", std::nullopt, false,
                std::to_string(world.get<sim::RainSim>().drops().size()) + " drops; profile mode"});
}

}  // namespace

void bench_rain(BenchReport& report, bool quick) {
    bench_sim(report, quick ? 120 : 600, "mostly at rest, 29 km/h", {1.0f, 40.0f}, 8.0f);
    // At 100 km/h the air drives drops up the glass (step_cell, merges, trails); drops
    // above the slide mass also run, and the blades turn them into many particles.
    bench_sim(report, quick ? 120 : 600, "of 1-40 mg at 100 km/h", {1.0f, 40.0f}, 100.0f / 3.6f);
    // A stress case, not rain: a raindrop breaks up above about 65 mg, so these are
    // merged drops, 5,000 of them topped up every tick as the blades sweep them off.
    bench_sim(report, quick ? 120 : 600, "of 200-500 mg at 100 km/h (stress)", {200.0f, 500.0f}, 100.0f / 3.6f,
              std::nullopt);
    bench_height_map(report, quick ? 3 : 10);
    bench_reference(report, 5);
    bench_pass(report, 640, 360, quick ? 2 : 5);
}

}  // namespace game
