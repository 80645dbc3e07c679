#include "game/bench/FluidBench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "effects/fluid/FluidPass.h"
#include "effects/scene/Camera.h"
#include "effects/scene/FrameContext.h"
#include "game/DataPaths.h"
#include "game/bench/BenchSupport.h"
#include "game/bench/SubsystemTimer.h"
#include "game/replay/ReplayCheck.h"
#include "game/replay/ReplayReader.h"
#include "game/session/GameSession.h"
#include "game/stage/RenderStage.h"
#include "sim/fluid/FluidScenes.h"
#include "sim/fluid/FluidTank.h"
#include "sim/objects/ThrownObjects.h"

namespace game {

namespace {

using Clock = std::chrono::steady_clock;
constexpr float kDegPerRad = 57.2957795f;

// The fluid pass alone over a plain background: scene targets, lighting and a camera.
struct FluidStage {
    FluidStage(int w, int h)
        : width(w),
          height(h),
          stage(bench_level(), {.width = w,
                                .height = h,
                                .passes = effects::PassSet::of({"fluid"}),
                                .environment_size = 16,
                                .shadow_map_size = 256}),
          targets(stage.targets()),
          pass(stage.pass<effects::FluidPass>()) {}

    static sim::LevelDesc bench_level() {
        sim::LevelDesc l;
        l.id = "fluid_bench";
        return l;
    }

    void look(glm::vec3 eye, glm::vec3 target, float fov_deg) {
        sim::CameraView v;
        v.eye = eye;
        v.target = target;
        v.fov_y_deg = fov_deg;
        camera = effects::make_camera(v, float(width) / float(height));
    }

    void render(const effects::FluidView& view) {
        const float sky[4] = {0.35f, 0.45f, 0.55f, 1.0f}, far = 1.0f;
        glClearNamedFramebufferfv(targets.hdr().id(), GL_COLOR, 0, sky);
        glClearNamedFramebufferfv(targets.hdr().id(), GL_DEPTH, 0, &far);
        pass.draw(stage.context(camera), view);
    }

    // A texture's texels, GL row order.
    std::vector<float> read(const effects::gl::Texture& t, int channels) const {
        std::vector<float> out(size_t(width) * size_t(height) * size_t(channels));
        glGetTextureImage(t.id(), 0, channels == 1 ? GL_RED : GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(float)),
                          out.data());
        return out;
    }

    // View-space ray through pixel (x, y) (GL rows), z = -1, as the shaders make it.
    glm::vec3 ray(int x, int y) const {
        float nx = (float(x) + 0.5f) / float(width) * 2.0f - 1.0f, ny = (float(y) + 0.5f) / float(height) * 2.0f - 1.0f;
        return {nx / camera.proj[0][0], ny / camera.proj[1][1], -1.0f};
    }

    int width, height;
    RenderStage stage;
    effects::SceneTargets& targets;
    effects::FluidPass& pass;
    effects::Camera camera;
};

// The analytic shapes: where the eye ray through a pixel meets them (view space).
struct ExactHit {
    bool hit = false;
    float depth = 0.0f;  // view distance
    glm::vec3 normal{0.0f};
};

struct AnalyticShape {
    QualityShape shape;
    glm::vec3 centre{0.0f, 5.0f, 0.0f};
    float radius = 0.5f;                 // sphere
    glm::vec3 half{0.3f, 0.3f, 0.3f};    // box
    glm::mat3 rotation{1.0f};            // box, world

    ExactHit hit(const effects::Camera& cam, glm::vec3 ray) const {
        ExactHit h;
        const glm::vec3 c(cam.view * glm::vec4(centre, 1.0f));
        if (shape == QualityShape::Sphere) {
            float a = glm::dot(ray, ray), b = glm::dot(ray, c), k = glm::dot(c, c) - radius * radius;
            float disc = b * b - a * k;
            if (disc <= 0.0f) return h;
            h.depth = (b - std::sqrt(disc)) / a;
            h.normal = (ray * h.depth - c) / radius;
            h.hit = true;
            return h;
        }
        const glm::mat3 rv = glm::mat3(cam.view) * rotation;  // box axes in view space
        const glm::mat3 to_box = glm::transpose(rv);
        glm::vec3 o = to_box * -c, d = to_box * ray;
        float t0 = -1e30f, t1 = 1e30f;
        int axis = 0;
        float sign = 1.0f;
        for (int k = 0; k < 3; ++k) {
            float inv = 1.0f / d[k];
            float ta = (-half[k] - o[k]) * inv, tb = (half[k] - o[k]) * inv;
            float s = -1.0f;
            if (ta > tb) std::swap(ta, tb), s = 1.0f;
            if (ta > t0) t0 = ta, axis = k, sign = s;
            t1 = std::min(t1, tb);
        }
        if (t1 <= t0 || t0 <= 0.0f) return h;
        h.hit = true;
        h.depth = t0;
        glm::vec3 n(0.0f);
        n[axis] = sign;
        h.normal = rv * n;
        return h;
    }

    // Particles on the rest lattice inside the shape, their spheres reaching its surface.
    std::vector<glm::vec3> particles(float r) const {
        std::vector<glm::vec3> out;
        const float s = 2.0f * r;
        const float reach = shape == QualityShape::Sphere ? radius : glm::length(half);
        const int n = int(std::ceil(reach / s));
        for (int k = -n; k <= n; ++k)
            for (int j = -n; j <= n; ++j)
                for (int i = -n; i <= n; ++i) {
                    glm::vec3 p(float(i) * s, float(j) * s, float(k) * s);
                    if (shape == QualityShape::Sphere) {
                        if (glm::length(p) > radius - r) continue;
                        out.push_back(centre + p);
                    } else {
                        glm::vec3 q = p + glm::vec3(0.5f * s);  // cell centres fill the box evenly
                        if (std::fabs(q.x) > half.x - r || std::fabs(q.y) > half.y - r || std::fabs(q.z) > half.z - r)
                            continue;
                        out.push_back(centre + rotation * q);
                    }
                }
        return out;
    }
};

constexpr float kQualityRadius = 0.015f;

AnalyticShape analytic(QualityShape shape) {
    AnalyticShape a{shape};
    if (shape == QualityShape::Box)
        a.rotation = glm::mat3(glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(0, 1, 0)) *
                               glm::rotate(glm::mat4(1.0f), 0.35f, glm::vec3(1, 0, 0)));
    return a;
}

effects::FluidView view_of(const std::vector<glm::vec3>& particles, float radius) {
    effects::FluidView v;
    v.particle_radius_m = radius;
    sim::anisotropic_kernels(particles, effects::anisotropy_for(radius), v.body);
    return v;
}

void look_at_shape(FluidStage& stage, const AnalyticShape& a) {
    stage.look(a.centre + glm::vec3(0.0f, 0.0f, 2.0f), a.centre, 40.0f);
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    size_t k = std::min(v.size() - 1, size_t(p * double(v.size())));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
}

float angle_deg(glm::vec3 a, glm::vec3 b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)) * kDegPerRad;
}

}  // namespace

SmoothingQuality measure_smoothing(QualityShape shape, const effects::FluidSmoothing& smoothing, int width,
                                   int height) {
    FluidStage stage(width, height);
    const AnalyticShape a = analytic(shape);
    look_at_shape(stage, a);
    stage.pass.set_smoothing(smoothing);
    stage.render(view_of(a.particles(kQualityRadius), kQualityRadius));
    const std::vector<float> depth = stage.read(stage.pass.body_front(), 1);
    const std::vector<float> normal = stage.read(stage.pass.body_front_normal(), 4);
    std::vector<double> depth_err;
    double sil = 0.0, inner = 0.0;
    int nsil = 0, ninner = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * size_t(width) + size_t(x);
            const glm::vec3 ray = stage.ray(x, y);
            const ExactHit h = a.hit(stage.camera, ray);
            if (!h.hit || !(depth[i] > 0.0f && depth[i] < 5e5f)) continue;
            depth_err.push_back(std::fabs(double(depth[i] - h.depth)));
            const glm::vec3 n(normal[4 * i], normal[4 * i + 1], normal[4 * i + 2]);
            if (glm::dot(n, n) < 0.25f) continue;
            const float err = angle_deg(n, h.normal);
            if (angle_deg(h.normal, -ray) > 60.0f) {
                sil += err;
                ++nsil;
            } else {
                inner += err;
                ++ninner;
            }
        }
    SmoothingQuality q;
    q.pixels = int(depth_err.size());
    for (double e : depth_err) q.depth_mean_m += e;
    if (q.pixels) q.depth_mean_m /= q.pixels;
    q.depth_p95_m = percentile(depth_err, 0.95);
    q.silhouette_normal_deg = nsil ? sil / nsil : 0.0;
    q.interior_normal_deg = ninner ? inner / ninner : 0.0;
    return q;
}

ExitRayQuality measure_exit_rays(int width, int height) {
    FluidStage stage(width, height);
    const AnalyticShape a = analytic(QualityShape::Sphere);
    look_at_shape(stage, a);
    stage.pass.set_smoothing(effects::FluidSmoothing::defaults(effects::SmoothingMethod::PlaneFit));
    stage.pass.set_exit_ray_probe(true);
    stage.render(view_of(a.particles(kQualityRadius), kQualityRadius));
    const std::vector<float> probe = stage.read(stage.targets.colour(), 4);
    const float eta = stage.pass.look().ior;
    const glm::vec3 c(stage.camera.view * glm::vec4(a.centre, 1.0f));
    std::vector<double> err;
    int converged = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * size_t(width) + size_t(x);
            const glm::vec3 out(probe[4 * i], probe[4 * i + 1], probe[4 * i + 2]);
            if (glm::dot(out, out) < 0.25f) continue;
            const glm::vec3 ray = stage.ray(x, y);
            const ExactHit h = a.hit(stage.camera, ray);
            const glm::vec3 d = glm::normalize(ray);
            if (!h.hit || angle_deg(h.normal, -d) > 45.0f) continue;
            // Exact double refraction through the sphere.
            const glm::vec3 p1 = ray * h.depth;
            const glm::vec3 t1 = glm::refract(d, h.normal, 1.0f / eta);
            const glm::vec3 p2 = p1 - 2.0f * glm::dot(t1, p1 - c) * t1;
            const glm::vec3 n2 = (p2 - c) / a.radius;
            const glm::vec3 t2 = glm::refract(t1, -n2, eta);
            if (glm::dot(t2, t2) < 0.5f) continue;  // total internal reflection
            err.push_back(angle_deg(out, t2));
            converged += probe[4 * i + 3] > 0.5f ? 1 : 0;
        }
    ExitRayQuality q;
    q.rays = int(err.size());
    for (double e : err) q.mean_deg += e;
    if (q.rays) {
        q.mean_deg /= q.rays;
        q.converged = double(converged) / q.rays;
    }
    q.p95_deg = percentile(err, 0.95);
    return q;
}

namespace {

struct Scene {
    const char* name;
    sim::FluidScene fluid;
    glm::vec3 eye_offset;
};

// The stage's stage times averaged over `frames` after one warm-up frame.
effects::FluidStageTimes time_frames(FluidStage& stage, const effects::FluidView& view, int frames) {
    stage.pass.set_profiling(true);
    stage.render(view);
    effects::FluidStageTimes sum;
    for (int f = 0; f < frames; ++f) {
        stage.render(view);
        const effects::FluidStageTimes& t = stage.pass.stage_times();
        sum.depth_ms += t.depth_ms / frames;
        sum.smoothing_ms += t.smoothing_ms / frames;
        sum.normals_ms += t.normals_ms / frames;
        sum.refraction_ms += t.refraction_ms / frames;
    }
    return sum;
}

// Simulates a benchmark scene for `ticks` on two threads; returns ms per tick.
double settle(sim::ParticleFluid& fluid, int ticks) {
    sim::JobPool jobs(2);
    auto start = Clock::now();
    for (int t = 0; t < ticks; ++t) fluid.step(sim::kTickSeconds, {0.0f, -9.81f, 0.0f}, {}, jobs);
    return seconds_since(start) * 1e3 / std::max(ticks, 1);
}

effects::FluidView scene_view(const sim::ParticleFluid& fluid, double* aniso_ms) {
    effects::FluidView v;
    auto start = Clock::now();
    effects::make_fluid_view(fluid, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.0f, 0.0f)), glm::vec3(0.0f), v);
    if (aniso_ms) *aniso_ms = seconds_since(start) * 1e3;
    return v;
}

void look_at_box(FluidStage& stage, glm::vec3 size) {
    const glm::vec3 centre = glm::vec3(0.0f, 2.0f, 0.0f) + glm::vec3(0.5f * size.x, 0.3f * size.y, 0.5f * size.z);
    stage.look(centre + glm::vec3(0.3f * size.x, 0.9f * size.y, 1.6f * size.x), centre, 50.0f);
}

void bench_tank_sim(BenchReport& report, bool quick) {
    GameSession s = GameSession::open("harbour", 2);
    const sim::FluidTank* tank = s.world->find<sim::FluidTank>();
    if (!tank) return;
    std::vector<std::string> names = s.world->subsystem_names();
    const size_t index = size_t(std::find(names.begin(), names.end(), "fluid") - names.begin());
    SubsystemTimer timer(names.size());
    const int ticks = quick ? 120 : 480;
    // Only ticks that stepped the liquid count: asleep, the tank costs next to nothing,
    // and averaging those in would hide the cost of a sloshing tank. A tick steps it if
    // the tank was awake before or after (waking resets the calm count, so it cannot
    // fall asleep again on the tick it woke).
    int awake = 0;
    double awake_s = 0.0;
    for (int t = 0; t < ticks; ++t) {
        if (t % 120 == 20)  // a stone into the tank now and then: the busy case
            s.world->get<sim::ThrownObjects>().launch({0.22f, 2600.0f, 0.0f}, s.world->level().tank_spot + glm::vec3(0, 2.5f, 0),
                                                      {0, 0, 1}, {0, 0, 0});
        const bool asleep_before = tank->asleep();
        const double before_s = timer.total_seconds()[index];
        s.world->step({}, &timer);
        if (!asleep_before || !tank->asleep()) {
            ++awake;
            awake_s += timer.total_seconds()[index] - before_s;
        }
    }
    report.add({"fluid", "sim per awake tick, tank of " + std::to_string(tank->fluid().size()) + " particles",
                awake ? awake_s * 1e3 / awake : 0.0, "ms", 6.0, false, "2 threads, a stone every 2 s, wall clock"});
    report.add({"fluid", "awake ticks of the tank", double(awake), "ticks", std::nullopt, false,
                "of " + std::to_string(ticks) + "; asleep ticks " +
                    fmt("%.3f ms each", (timer.total_seconds()[index] - awake_s) * 1e3 / std::max(ticks - awake, 1))});
    // The same liquid's cost in CPU time on one thread: what the machine's other load
    // does not inflate (the wall clock above waits for a shared core).
    sim::ParticleFluid fluid = tank->fluid();
    sim::JobPool one(1);
    timespec t0{}, t1{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t0);
    const int cpu_ticks = quick ? 60 : 240;
    for (int t = 0; t < cpu_ticks; ++t) fluid.step(sim::kTickSeconds, {0.0f, -9.81f, 0.0f}, {}, one);
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t1);
    const double cpu_ms = (double(t1.tv_sec - t0.tv_sec) * 1e3 + double(t1.tv_nsec - t0.tv_nsec) * 1e-6) / cpu_ticks;
    report.add({"fluid", "sim per tick, same tank, CPU time on 1 thread", cpu_ms, "ms", std::nullopt, false,
                "half of it per core with 2 threads"});
}

// Times the liquid's step on one tick, CPU time of the calling thread and wall clock.
class FluidStepTimer final : public sim::StepObserver {
public:
    explicit FluidStepTimer(size_t index) : index_(index) {}
    void before(size_t i) override {
        if (i != index_) return;
        wall_ = Clock::now();
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpu_);
    }
    void after(size_t i) override {
        if (i != index_) return;
        timespec now{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
        cpu_ms = double(now.tv_sec - cpu_.tv_sec) * 1e3 + double(now.tv_nsec - cpu_.tv_nsec) * 1e-6;
        wall_ms = seconds_since(wall_) * 1e3;
    }
    double cpu_ms = 0.0, wall_ms = 0.0;

private:
    size_t index_;
    Clock::time_point wall_;
    timespec cpu_{};
};

// The liquid of replays/harbour_tank (a float and a stone thrown in, the splash its
// timedemo's slowest frames wait on), per awake tick: CPU time on one thread, and the
// wall clock on two. The replay's hashes are checked on the way.
void bench_tank_replay(BenchReport& report) {
    const Replay replay = read_replay(data_dir() / "replays" / "harbour_tank.replay");
    for (int threads : {1, 2}) {
        GameSession s = GameSession::open(replay.header.level_id, threads, replay.header.seed);
        const sim::FluidTank* tank = s.world->find<sim::FluidTank>();
        if (!tank) return;
        const std::vector<std::string> names = s.world->subsystem_names();
        FluidStepTimer timer(size_t(std::find(names.begin(), names.end(), "fluid") - names.begin()));
        ReplayChecker checker(replay);
        std::vector<double> cpu_ms, wall_ms;
        for (const sim::TickInput& input : replay.inputs) {
            const bool asleep_before = tank->asleep();
            s.world->step(input, &timer);
            if (auto divergence = checker.after_step(*s.world)) {
                std::cerr << "bench: harbour_tank desynced: " << divergence->message << "\n";
                return;
            }
            if (asleep_before && tank->asleep()) continue;
            cpu_ms.push_back(timer.cpu_ms);
            wall_ms.push_back(timer.wall_ms);
        }
        const double ticks = double(std::max<size_t>(cpu_ms.size(), 1));
        const std::string awake = std::to_string(cpu_ms.size()) + " awake ticks of " + std::to_string(replay.inputs.size());
        if (threads == 1) {
            double sum = 0.0;
            for (double ms : cpu_ms) sum += ms;
            report.add({"fluid", "harbour_tank liquid per awake tick, CPU time, 1 thread", sum / ticks, "ms",
                        std::nullopt, false, awake});
            report.add({"fluid", "harbour_tank liquid per awake tick, CPU time, 1 thread, p95", percentile(cpu_ms, 0.95),
                        "ms", std::nullopt, false, awake});
        } else {
            double sum = 0.0;
            for (double ms : wall_ms) sum += ms;
            report.add({"fluid", "harbour_tank liquid per awake tick, wall clock, 2 threads", sum / ticks, "ms",
                        std::nullopt, false, awake});
        }
    }
}

}  // namespace

void bench_fluid(BenchReport& report, bool quick) {
    std::cerr << "bench: fluid sim\n";
    bench_tank_sim(report, quick);
    bench_tank_replay(report);

    const int frames = quick ? 1 : 4;
    FluidStage stage(640, 480);
    Scene scenes[2] = {{"wave", sim::wave_scene(100000), {}}, {"step", sim::step_scene(50000), {}}};
    double wave_plane_smooth = 0.0, wave_bilateral_smooth = 0.0;
    effects::FluidView wave_view;
    for (Scene& sc : scenes) {
        std::cerr << "bench: fluid " << sc.name << " scene\n";
        sim::ParticleFluid fluid(sc.fluid.params);
        fluid.set_boxes(sc.fluid.boxes);
        fluid.add_particles(sc.fluid.particles);
        const std::string tag = std::string(sc.name) + " (" + std::to_string(fluid.size() / 1000) + "k)";
        const double tick_ms = settle(fluid, quick ? 12 : 40);
        report.add({"fluid", tag + " sim per tick", tick_ms, "ms", std::nullopt, false, "2 threads; not real-time"});
        double aniso_ms = 0.0;
        effects::FluidView view = scene_view(fluid, &aniso_ms);
        report.add({"fluid", tag + " anisotropic kernels (CPU)", aniso_ms, "ms", std::nullopt, false, "1 thread"});
        look_at_box(stage, sc.fluid.params.box_size_m);
        for (auto method : {effects::SmoothingMethod::PlaneFit, effects::SmoothingMethod::Bilateral}) {
            effects::FluidSmoothing sm = effects::FluidSmoothing::defaults(method);
            stage.pass.set_smoothing(sm);
            const effects::FluidStageTimes t = time_frames(stage, view, frames);
            const std::string m = std::string(effects::smoothing_name(method)) + " " + std::to_string(sm.kernel_size) +
                                  "x" + std::to_string(sm.kernel_size) + " x" + std::to_string(sm.iterations);
            report.add({"fluid", tag + " " + m + ": depth maps", t.depth_ms, "ms"});
            report.add({"fluid", tag + " " + m + ": smoothing", t.smoothing_ms, "ms"});
            report.add({"fluid", tag + " " + m + ": normals", t.normals_ms, "ms"});
            report.add({"fluid", tag + " " + m + ": refraction", t.refraction_ms, "ms"});
            report.add({"fluid", tag + " " + m + ": total", t.total(), "ms", std::nullopt, false,
                        "640x480, llvmpipe, glFinish per step"});
            if (&sc == &scenes[0])
                (method == effects::SmoothingMethod::PlaneFit ? wave_plane_smooth : wave_bilateral_smooth) = t.smoothing_ms;
        }
        if (&sc == &scenes[0]) wave_view = std::move(view);
    }
    report.add({"fluid", "wave: bilateral 7x7 x22 / plane fit 9x9 x3 smoothing time", wave_bilateral_smooth / wave_plane_smooth,
                "x", 3.0, true, "the seed got 2.1x"});

    std::cerr << "bench: fluid quality\n";
    const effects::SmoothingMethod methods[3] = {effects::SmoothingMethod::PlaneFit, effects::SmoothingMethod::Bilateral,
                                                 effects::SmoothingMethod::NarrowRange};
    SmoothingQuality quality[3];
    for (int k = 0; k < 3; ++k)
        quality[k] = measure_smoothing(QualityShape::Sphere, effects::FluidSmoothing::defaults(methods[k]), 640, 480);
    for (int k = 0; k < 3; ++k) {
        const SmoothingQuality& q = quality[k];
        // Plane fitting must beat the bilateral baseline at the silhouette.
        std::optional<double> target;
        if (k == 0) target = quality[1].silhouette_normal_deg;
        report.add({"fluid", "sphere: " + std::string(effects::smoothing_name(methods[k])) + " silhouette normal error",
                    q.silhouette_normal_deg, "deg", target, false,
                    "interior " + fmt("%.2f deg", q.interior_normal_deg) + ", depth mean " + fmt("%.4f m", q.depth_mean_m) +
                        ", p95 " + fmt("%.4f m", q.depth_p95_m)});
    }
    const ExitRayQuality exit = measure_exit_rays(640, 480);
    report.add({"fluid", "sphere: secant exit ray vs exact double refraction (mean)", exit.mean_deg, "deg",
                std::nullopt, false,
                "p95 " + fmt("%.2f deg", exit.p95_deg) + ", converged " + fmt("%.0f%%", 100.0 * exit.converged)});

    std::cerr << "bench: fluid smoothing kernels\n";
    look_at_box(stage, sim::wave_scene(1000).params.box_size_m);
    const std::vector<int> kernels = quick ? std::vector<int>{7, 13} : std::vector<int>{7, 9, 11, 13};
    for (auto method : {effects::SmoothingMethod::PlaneFit, effects::SmoothingMethod::Bilateral})
        for (int k : kernels) {
            effects::FluidSmoothing sm = effects::FluidSmoothing::defaults(method);
            sm.kernel_size = k;
            sm.iterations = 1;
            stage.pass.set_smoothing(sm);
            const effects::FluidStageTimes t = time_frames(stage, wave_view, frames);
            report.add({"fluid", "wave: " + std::string(effects::smoothing_name(method)) + " " + std::to_string(k) + "x" +
                                     std::to_string(k) + " one iteration",
                        t.smoothing_ms, "ms"});
        }
    for (int it : quick ? std::vector<int>{1, 5} : std::vector<int>{1, 3, 5}) {
        effects::FluidSmoothing sm = effects::FluidSmoothing::defaults(effects::SmoothingMethod::PlaneFit);
        sm.iterations = it;
        stage.pass.set_smoothing(sm);
        report.add({"fluid", "wave: plane_fit 9x9 x" + std::to_string(it) + " smoothing",
                    time_frames(stage, wave_view, frames).smoothing_ms, "ms"});
    }
    for (int it : quick ? std::vector<int>{10, 30} : std::vector<int>{10, 22, 30}) {
        effects::FluidSmoothing sm = effects::FluidSmoothing::defaults(effects::SmoothingMethod::Bilateral);
        sm.iterations = it;
        stage.pass.set_smoothing(sm);
        report.add({"fluid", "wave: bilateral 7x7 x" + std::to_string(it) + " smoothing",
                    time_frames(stage, wave_view, frames).smoothing_ms, "ms"});
    }

    std::cerr << "bench: fluid particle counts\n";
    stage.pass.set_smoothing(effects::FluidSmoothing::defaults(effects::SmoothingMethod::PlaneFit));
    for (int count : {25000, 50000, 100000}) {
        sim::FluidScene sc = sim::wave_scene(count);
        sim::ParticleFluid fluid(sc.params);
        fluid.add_particles(sc.particles);
        settle(fluid, quick ? 6 : 20);
        effects::FluidView view = scene_view(fluid, nullptr);
        look_at_box(stage, sc.params.box_size_m);
        report.add({"fluid", "wave " + std::to_string(count / 1000) + "k: plane fit frame",
                    time_frames(stage, view, frames).total(), "ms", std::nullopt, false, "640x480"});
    }

    std::cerr << "bench: fluid screen coverage\n";
    {
        GameSession s = GameSession::open("harbour", 2);
        for (int t = 0; t < 60; ++t) s.world->step({});
        effects::FluidView view;
        effects::gather_fluid_view(*s.world, view);
        const glm::vec3 centre(view.tank_to_world * glm::vec4(0.5f * view.tank_size, 1.0f));
        // Pull the camera back until the rectangle covers a quarter of the screen; close
        // in until it covers all of it.
        auto coverage = [&](float distance) {
            stage.look(centre + glm::normalize(glm::vec3(0.3f, 0.35f, -1.0f)) * distance, centre, 50.0f);
            stage.pass.set_profiling(false);
            stage.render(view);
            glm::ivec4 r = stage.pass.last_rect();
            return double(r.z - r.x) * double(r.w - r.y) / (640.0 * 480.0);
        };
        float lo = 1.0f, hi = 30.0f;
        for (int k = 0; k < 20; ++k) {
            float mid = 0.5f * (lo + hi);
            (coverage(mid) > 0.25 ? lo : hi) = mid;
        }
        const double quarter_cover = coverage(hi);
        const double quarter_ms = time_frames(stage, view, frames + 1).total();
        const double full_cover = coverage(1.2f);
        const double full_ms = time_frames(stage, view, frames + 1).total();
        report.add({"fluid", "tank covering " + fmt("%.0f%%", 100.0 * quarter_cover) + " of the screen", quarter_ms,
                    "ms", std::nullopt, false, "640x480"});
        report.add({"fluid", "tank covering " + fmt("%.0f%%", 100.0 * full_cover) + " of the screen", full_ms, "ms",
                    std::nullopt, false, "640x480"});
        // The ratio below means something only if the close view really fills the screen.
        report.add({"fluid", "close view's screen coverage", 100.0 * full_cover, "%", 95.0, true,
                    "the full-screen case of the ratio below"});
        report.add({"fluid", "quarter-screen tank / full-screen tank", quarter_ms / full_ms, "x", 0.30, false,
                    "work confined to the tank's rectangle"});

        // Beside the glass looking along it, half the tank behind the eye (on the pier,
        // or on the boat leaving it): the rectangle is the box's part in front of the near
        // plane, not the whole screen.
        const glm::vec3 beside(view.tank_to_world * glm::vec4(0.5f * view.tank_size.x, 0.8f * view.tank_size.y, -0.05f, 1.0f));
        const glm::vec3 along(view.tank_to_world * glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
        stage.look(beside, beside + along, 50.0f);
        stage.pass.set_profiling(false);
        stage.render(view);
        const glm::ivec4 r = stage.pass.last_rect();
        const double straddle_cover = double(r.z - r.x) * double(r.w - r.y) / (640.0 * 480.0);
        const double straddle_ms = time_frames(stage, view, frames + 1).total();
        report.add({"fluid", "tank straddling the eye, covering " + fmt("%.0f%%", 100.0 * straddle_cover) + " of the screen",
                    straddle_ms, "ms", std::nullopt, false, "640x480"});
        report.add({"fluid", "tank straddling the eye / full-screen tank in view", straddle_ms / full_ms, "x", 1.0,
                    false, "the box clipped at the near plane"});
    }
}

}  // namespace game
