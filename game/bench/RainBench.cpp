#include "game/bench/RainBench.h"

#include <chrono>
#include <ctime>
#include <cstdio>
#include <string>
#include <vector>

#include "effects/gl/Gl.h"
#include "effects/rain/DropHeightMap.h"
#include "effects/rain/MetaballReference.h"
#include "effects/rain/RainPass.h"
#include "effects/Renderer.h"
#include "game/capture/FrameCapture.h"
#include "game/level/LevelLoader.h"
#include "game/session/GameSession.h"
#include "sim/rain/RainSim.h"

namespace game {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// This thread's CPU time: what one core spends, whatever else the machine is running.
double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

std::string fmt(const char* format, double v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

// The harbour car's glass with `count` drops on it.
sim::RainSim busy_glass(int count) {
    LoadedLevel level = load_level("harbour");
    sim::RainSim rain({}, level.sim.rain.glass_lower, level.sim.rain.glass_upper, 4242);
    sim::Rng rng(77, 1);
    const sim::GlassSurface& g = rain.glass();
    while (int(rain.drops().size()) < count)
        rain.add_drop({rng.unit() * float(g.cols()) * g.cell_m(), rng.unit() * float(g.rows()) * g.cell_m()},
                      rng.range(1.0f, 40.0f));
    return rain;
}

void top_up(sim::RainSim& rain, sim::Rng& rng, int count) {
    const sim::GlassSurface& g = rain.glass();
    while (int(rain.drops().size()) < count)
        rain.add_drop({rng.unit() * float(g.cols()) * g.cell_m(), rng.unit() * float(g.rows()) * g.cell_m()},
                      rng.range(1.0f, 20.0f));
}

void bench_sim(BenchReport& report, int ticks) {
    sim::RainSim rain = busy_glass(5000);
    sim::Rng rng(78, 1);
    const sim::RainForces forces = rain.forces_for(8.0f, {0.0f, 0.0f}, {0.0f, -9.81f, 0.0f});
    double wall = 0.0, cpu = 0.0, particles = 0.0;
    for (int t = 0; t < ticks; ++t) {
        top_up(rain, rng, 5000);  // the wipers clear drops: keep 5,000 on the glass
        const auto start = Clock::now();
        const double cpu_start = thread_cpu_seconds();
        rain.advance(1.0f, sim::WiperMode::High, 8.0f, forces, 1.0f / 60.0f);
        cpu += thread_cpu_seconds() - cpu_start;
        wall += seconds_since(start);
        particles += double(rain.particles().size());
    }
    report.add({"rain", "rain sim per tick, 5000 drops, two wipers on high (CPU time)", cpu * 1e3 / ticks, "ms", 1.0,
                false, "1 thread; wall " + fmt("%.3f", wall * 1e3 / ticks) + " ms; mean " +
                           fmt("%.0f", particles / ticks) + " wiper particles"});
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
    report.add({"rain", "height map: splat, compress, normals @1024x512", seconds_since(start) * 1e3 / frames, "ms",
                std::nullopt, false, std::to_string(balls.size()) + " metaballs; glFinish around the frames"});
}

std::vector<effects::SurfaceSample> read_back(const effects::DropHeightMap& map) {
    std::vector<float> rgba(size_t(map.width()) * size_t(map.height()) * 4);
    glGetTextureImage(map.surface().id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
    std::vector<effects::SurfaceSample> out(size_t(map.width()) * size_t(map.height()));
    for (size_t k = 0; k < out.size(); ++k) {
        const float x = rgba[4 * k], y = rgba[4 * k + 1];
        out[k] = {{x, y, std::sqrt(std::max(1.0f - x * x - y * y, 0.0f))}, rgba[4 * k + 3] > 0.5f ? rgba[4 * k + 2] : 0.0f};
    }
    return out;
}

void bench_reference(BenchReport& report, int frames) {
    glm::vec2 size;
    const std::vector<effects::RainMetaball> scene = effects::merged_drop_scene(size);
    const int w = 512, h = 256;
    effects::DropHeightMap map(w, h);
    map.update(scene, size, 1.0f);
    glFinish();
    auto start = Clock::now();
    for (int f = 0; f < frames; ++f) map.update(scene, size, 1.0f);
    glFinish();
    const double fast_s = seconds_since(start) / frames;
    const std::vector<effects::SurfaceSample> fast = read_back(map);

    start = Clock::now();
    const std::vector<effects::SurfaceSample> slow = effects::reference_surface(scene, size, w, h);
    const double slow_s = seconds_since(start);
    size_t wet = 0;
    const double angle = effects::mean_normal_angle_deg(fast, slow, wet);
    const std::string res = std::to_string(w) + "x" + std::to_string(h);
    report.add({"rain", "2D metaball path @" + res + " (GPU)", fast_s * 1e3, "ms", std::nullopt, false,
                std::to_string(scene.size()) + " merged drops"});
    report.add({"rain", "3D metaball reference @" + res + " (CPU)", slow_s * 1e3, "ms", std::nullopt, false,
                "iso-surface by bisection, 1 thread"});
    report.add({"rain", "3D reference / 2D path time", slow_s / fast_s, "x", 20.0, true});
    report.add({"rain", "mean normal angle error, 2D vs 3D", angle, "deg", 5.0, false,
                std::to_string(wet) + " texels wet in both"});
}

// The whole rain pass in the driver's view of the harbour car, parked in heavy rain
// with the wipers on low: height map, scene copy with mips, windshield.
void bench_pass(BenchReport& report, int width, int height, int frames) {
    GameSession s = GameSession::open("harbour", 1);
    for (uint32_t t = 0; t < 300; ++t) {
        sim::TickInput in;
        in.set(sim::Control::Camera, t == 0);
        in.set(sim::Control::RainUp, t == 2 || t == 4 || t == 6 || t == 8);
        in.set(sim::Control::Wipers, t == 100 || t == 102);
        s.world->step(in);
    }
    effects::Renderer renderer(s.level.scene, *s.world, {.timing = effects::gl::TimingMode::Profile});
    FrameCapture capture(width, height);
    renderer.render(*s.world, capture.output());
    double ms = 0.0;
    for (int f = 0; f < frames; ++f) {
        s.world->step({});
        renderer.render(*s.world, capture.output());
        for (const auto& p : renderer.pass_times())
            if (p.name == "rain") ms += p.ms;
    }
    report.add({"rain", "rain pass in the driver's view @" + std::to_string(width) + "x" + std::to_string(height),
                ms / frames, "ms", std::nullopt, false,
                std::to_string(s.world->get<sim::RainSim>().drops().size()) + " drops; profile mode"});
}

}  // namespace

void bench_rain(BenchReport& report, bool quick) {
    bench_sim(report, quick ? 120 : 600);
    bench_height_map(report, quick ? 3 : 10);
    bench_reference(report, quick ? 3 : 10);
    bench_pass(report, 640, 360, quick ? 2 : 5);
}

}  // namespace game
