#include "game/bench/EnergyBench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "effects/energy/EnergyPass.h"
#include "effects/energy/EnergyProbe.h"
#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/PipelineState.h"
#include "effects/gl/Program.h"
#include "effects/scene/FrameContext.h"
#include "game/bench/BenchSupport.h"
#include "game/stage/RenderStage.h"
#include "sim/weapon/EnergyField.h"
#include "sim/world/World.h"

namespace game {

namespace {

using Clock = std::chrono::steady_clock;
using sim::EnergySegment;

std::string size_name(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

effects::Camera bench_camera(int w, int h) {
    sim::CameraView v;
    v.eye = {0.0f, 2.0f, 12.0f};
    v.target = {0.0f, 1.0f, -10.0f};
    return effects::make_camera(v, float(w) / float(h));
}

// n segments as shots of up to 10 chained segments, fanned across the view at
// different depths, overlapping: the accuracy case.
std::vector<EnergySegment> volley(int n) {
    std::vector<EnergySegment> segs;
    const int shots = (n + 9) / 10;
    for (int k = 0; k < shots; ++k) {
        const int count = std::min(10, n - 10 * k);
        const float u = shots > 1 ? float(k) / float(shots - 1) : 0.5f;
        glm::vec3 p(-9.0f + 2.0f * u, -1.0f + 4.5f * u, -4.0f - 6.0f * u);
        const float seg_len = 18.0f / float(count);
        for (int i = 0; i < count; ++i) {
            glm::vec3 d = glm::normalize(glm::vec3(1.0f, 0.15f * std::sin(1.7f * float(i) + float(k)), 0.1f));
            segs.push_back({p, d, seg_len, 0.12f, 0.12f, 1.6f});
            p += d * seg_len;
        }
    }
    return segs;
}

// The scaling cases: shots as the weapon fires them (4 segments of 3.5 m, 1.1 m cut-off
// radius, a 14 m beam that sways a little), 25 of them spread over a 5 x 5 grid of the
// view at depths from 18 to 50 m, each crossing its own part of the screen in its own
// direction. The first n segments: 1 is the second segment of the centre shot, 100 is
// every shot.
std::vector<EnergySegment> spread_shots(const effects::Camera& cam, int n) {
    const glm::vec3 right(cam.view[0][0], cam.view[1][0], cam.view[2][0]);
    const glm::vec3 up(cam.view[0][1], cam.view[1][1], cam.view[2][1]);
    const glm::vec3 forward = -glm::vec3(cam.view[0][2], cam.view[1][2], cam.view[2][2]);
    const float tan_y = 1.0f / cam.proj[1][1], tan_x = 1.0f / cam.proj[0][0];
    std::vector<EnergySegment> segs;
    for (int k = 0; k < 25 && int(segs.size()) < n; ++k) {
        const int cell = (k + 12) % 25, i = cell % 5, j = cell / 5;  // the centre shot first
        const float depth = 18.0f + 8.0f * float((i + 2 * j) % 5);
        const glm::vec3 centre = cam.eye + depth * (forward + (-0.8f + 0.4f * float(i)) * tan_x * right +
                                                    (-0.7f + 0.35f * float(j)) * tan_y * up);
        const float a = 0.9f * float(cell);
        const glm::vec3 d = glm::normalize(std::cos(a) * right + 0.2f * std::sin(2.0f * a) * up - std::sin(a) * forward);
        glm::vec3 p = centre - 7.0f * d;
        for (int s = 0; s < 4; ++s) {
            const glm::vec3 sway = 0.1f * std::sin(1.3f * float(s) + a) * up;
            const glm::vec3 next = centre + (-7.0f + 3.5f * float(s + 1)) * d + sway;
            const glm::vec3 seg = next - p;
            segs.push_back({p, glm::normalize(seg), glm::length(seg), 0.12f, 0.12f, 1.1f});
            p = next;
        }
    }
    if (n == 1) return {segs[1]};
    segs.resize(size_t(n));
    return segs;
}

// Milliseconds per draw of raw H, averaged over `frames` after one warm-up draw.
double time_draw(effects::EnergyProbe& probe, effects::EnergyPass& pass, const effects::Camera& cam,
                 const std::vector<EnergySegment>& segs, int frames) {
    probe.draw_energy(pass, cam, segs);
    glFinish();
    auto start = Clock::now();
    for (int f = 0; f < frames; ++f) probe.draw_energy(pass, cam, segs);
    glFinish();
    return seconds_since(start) * 1e3 / frames;
}

// Mean relative error of the probe's H against the quadrature on a subsampled grid of
// rays (every `step` pixels), where the field is not negligible and the ray keeps
// 0.1 m from the singular points.
struct ErrorSample {
    std::vector<glm::ivec2> pixels;
    std::vector<double> reference;
};

ErrorSample reference_rays(const effects::EnergyProbe& probe, const effects::Camera& cam,
                           const std::vector<EnergySegment>& segs, const std::vector<glm::vec4>& analytic, int step) {
    const int w = probe.width(), h = probe.height();
    double peak = 0.0;
    for (const glm::vec4& p : analytic) peak = std::max(peak, double(p.x));
    ErrorSample out;
    for (int y = step / 2; y < h; y += step)
        for (int x = step / 2; x < w; x += step) {
            glm::dvec4 ndc((x + 0.5) / w * 2.0 - 1.0, (y + 0.5) / h * 2.0 - 1.0, 1.0, 1.0);
            glm::dvec4 far = glm::dmat4(cam.inv_view_proj) * ndc;
            glm::dvec3 q = glm::normalize(glm::dvec3(far) / far.w - glm::dvec3(cam.eye));
            const double s_end = analytic[size_t(y) * w + x].y;
            const double ref = sim::energy_along_ray(segs, glm::dvec3(cam.eye), q, s_end);
            if (ref < 1e-3 * peak || sim::energy_singular_distance(segs, glm::dvec3(cam.eye), q, s_end) < 0.1) continue;
            out.pixels.push_back({x, y});
            out.reference.push_back(ref);
        }
    return out;
}

double mean_relative_error(const ErrorSample& s, const std::vector<glm::vec4>& image, int width) {
    double sum = 0.0;
    for (size_t i = 0; i < s.pixels.size(); ++i)
        sum += std::fabs(double(image[size_t(s.pixels[i].y) * width + s.pixels[i].x].x) - s.reference[i]) / s.reference[i];
    return s.pixels.empty() ? 0.0 : sum / double(s.pixels.size());
}

void bench_accuracy(BenchReport& report, bool quick) {
    constexpr int kSize = 256;
    effects::EnergyProbe probe(kSize, kSize);
    effects::EnergyPass pass;
    const effects::Camera cam = bench_camera(kSize, kSize);
    const std::vector<EnergySegment> segs = volley(10);
    const int frames = quick ? 2 : 5;

    pass.method().march_samples = 0;
    probe.draw_energy(pass, cam, segs);
    const std::vector<glm::vec4> analytic = probe.read();
    const ErrorSample sample = reference_rays(probe, cam, segs, analytic, 4);
    const double analytic_error = mean_relative_error(sample, analytic, kSize);
    const double analytic_ms = time_draw(probe, pass, cam, segs, frames);
    const std::string where = "10 segments @" + size_name(kSize, kSize);
    report.add({"energy", "closed form " + where, analytic_ms, "ms", std::nullopt, false,
                "mean relative error " + fmt("%.2e", analytic_error) + " over " + std::to_string(sample.pixels.size()) +
                    " rays vs quadrature"});

    // Ray marching: 120 samples (the seed's comparison), then doubling until its error
    // reaches the closed form's or the samples run out.
    int samples = 120;
    double march_ms = 0.0, march_error = 0.0;
    const int max_samples = quick ? 960 : 3840;
    for (;; samples *= 2) {
        pass.method().march_samples = samples;
        probe.draw_energy(pass, cam, segs);
        march_error = mean_relative_error(sample, probe.read(), kSize);
        march_ms = time_draw(probe, pass, cam, segs, samples <= 240 ? frames : 1);
        report.add({"energy", "ray marching " + std::to_string(samples) + " samples " + where, march_ms, "ms",
                    std::nullopt, false, "mean relative error " + fmt("%.2e", march_error)});
        if (samples == 120)
            report.add({"energy", "ray marching 120 / closed form time", march_ms / analytic_ms, "x", std::nullopt,
                        false, "error " + fmt("%.2e", march_error) + " vs " + fmt("%.2e", analytic_error)});
        if (march_error <= analytic_error || samples * 2 > max_samples) break;
    }
    const bool reached = march_error <= analytic_error;
    report.add({"energy", "ray marching samples to match closed-form error", double(samples), "samples", std::nullopt,
                false,
                reached ? "reached" : "not reached: error still " + fmt("%.2e", march_error) + " at the largest count"});
    report.add({"energy", "time ratio ray marching / closed form at equal error", march_ms / analytic_ms, "x", 10.0,
                true,
                reached ? "at the matching sample count"
                        : "lower bound: at " + std::to_string(samples) + " samples, still less accurate"});
}

void bench_scaling(BenchReport& report, bool quick) {
    const int frames = quick ? 2 : 6;
    effects::EnergyPass pass;
    const struct {
        int w, h;
    } sizes[] = {{256, 256}, {512, 512}, {1280, 720}};
    double one_hd = 0.0, hundred_hd = 0.0;
    size_t one_pairs = 0, hundred_pairs = 0;
    for (auto [w, h] : sizes) {
        effects::EnergyProbe probe(w, h);
        const effects::Camera cam = bench_camera(w, h);
        for (int n : {1, 10, 100}) {
            const std::vector<EnergySegment> segs = spread_shots(cam, n);
            const double ms = time_draw(probe, pass, cam, segs, frames);
            const size_t tiles = pass.tiles().tiles.size(), pairs = pass.tiles().pairs();
            report.add({"energy", std::to_string(n) + " segments @" + size_name(w, h), ms, "ms", std::nullopt, false,
                        std::to_string(tiles) + " tiles shaded, " + std::to_string(pairs) + " tile-segment pairs (" +
                            fmt("%.1f", double(pairs) / double(std::max<size_t>(tiles, 1))) + " a tile)"});
            if (w == 1280 && n == 1) one_hd = ms, one_pairs = pairs;
            if (w == 1280 && n == 100) hundred_hd = ms, hundred_pairs = pairs;
        }
        if (w == 1280) {
            pass.method().tile_culling = false;
            const double ms = time_draw(probe, pass, cam, spread_shots(cam, 100), std::max(1, frames / 2));
            pass.method().tile_culling = true;
            report.add({"energy", "100 segments without tile culling @" + size_name(w, h), ms, "ms", std::nullopt,
                        false, "every pixel integrates every segment"});
        }
    }
    // Culling makes the cost follow the tile-segment pairs; 25 shots each over their own
    // part of the screen have many times the pairs of one segment, whatever the culling.
    report.add({"energy", "100 / 1 segments @1280x720", hundred_hd / one_hd, "x", 3.0, false,
                "with per-tile culling; 25 shots of 4 spread over the view vs one of their segments; " +
                    fmt("%.1f", double(hundred_pairs) / double(std::max<size_t>(one_pairs, 1))) + "x the pairs"});
}

// The real pass (glow ramp into the HDR scene colour, then the bloom) on scene-sized
// targets, with the camera inside a grown shot (4 segments, as the weapon fires them)
// so every tile of the screen has some of them; against a trivial fill of the same
// scene colour with the same additive blending, in the same run.
void bench_full_screen(BenchReport& report, bool quick) {
    constexpr int W = 1280, H = 720;
    const int frames = quick ? 3 : 10;
    sim::LevelDesc level;
    level.id = "energy_bench";
    // The scene's targets only: the bench draws the pass with its own segments.
    RenderStage stage(level, {.width = W, .height = H, .passes = {}, .environment_size = 16, .shadow_map_size = 256});
    const float far = 1.0f;
    glClearNamedFramebufferfv(stage.targets().hdr().id(), GL_DEPTH, 0, &far);  // sky everywhere
    sim::CameraView v;
    v.eye = {0.2f, 0.1f, 0.0f};
    v.target = {0.0f, 0.0f, -10.0f};
    const effects::Camera cam = effects::make_camera(v, float(W) / float(H));
    const effects::FrameContext frame = stage.context(cam);
    std::vector<EnergySegment> shot;
    glm::vec3 p(0.0f, 0.0f, 3.0f);
    for (int i = 0; i < 4; ++i) {
        glm::vec3 d = glm::normalize(glm::vec3(0.05f * float(i - 1), 0.03f, -1.0f));
        shot.push_back({p, d, 3.5f, 0.12f, 0.12f, 1.6f});
        p += d * 3.5f;
    }
    effects::EnergyPass pass;
    auto time_pass = [&](std::span<const EnergySegment> segments, float bloom) {
        pass.look().bloom = bloom;
        pass.draw(frame, segments);
        glFinish();
        auto start = Clock::now();
        for (int f = 0; f < frames; ++f) pass.draw(frame, segments);
        glFinish();
        return seconds_since(start) * 1e3 / frames;
    };
    const double glow_ms = time_pass(shot, 0.0f);
    // Of the full-resolution draw (the bloom's quarter-resolution one bins its own).
    const size_t tiles = pass.tiles().tiles.size(), pairs = pass.tiles().pairs();
    const double pass_ms = time_pass(shot, effects::EnergyLook{}.bloom);
    // The floor of any pass that integrates per pixel: one segment, still around the eye,
    // so every pixel of the screen does exactly one closed form.
    const double one_ms = time_pass(std::span(shot).first(1), 0.0f);
    const size_t one_tiles = pass.tiles().tiles.size(), one_pairs = pass.tiles().pairs();

    // The trivial fill: one full-screen triangle adding a constant to the same colour target.
    const effects::gl::Program fill = effects::gl::Program::from_sources(
        "energy_bench.fill",
        {{GL_VERTEX_SHADER,
          "#version 450 core\nvoid main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);"
          " gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }\n",
          "fill.vert"},
         {GL_FRAGMENT_SHADER, "#version 450 core\nout vec4 o;\nvoid main() { o = vec4(0.01, 0.02, 0.03, 0.0); }\n",
          "fill.frag"}});
    effects::gl::Framebuffer target = effects::gl::Framebuffer::create("energy_bench.fill");
    target.attach_colour(0, stage.targets().colour());
    target.check_complete();
    target.bind();
    glViewport(0, 0, W, H);
    effects::gl::apply({.blend = effects::gl::kAdd});
    fill.use();
    effects::gl::bind_empty_vertex_array();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
    auto start = Clock::now();
    for (int f = 0; f < frames; ++f) glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
    const double fill_ms = seconds_since(start) * 1e3 / frames;
    effects::gl::apply(effects::gl::kInitialState);
    report.add({"energy", "full-screen energy glow @1280x720", glow_ms, "ms", std::nullopt, false,
                std::to_string(tiles) + " tiles, " + fmt("%.1f", double(pairs) / double(std::max<size_t>(tiles, 1))) +
                    " segments a tile, no bloom"});
    report.add({"energy", "full-screen energy pass (glow + bloom) @1280x720", pass_ms, "ms", std::nullopt, false,
                "EnergyPass::draw on the HDR scene colour"});
    report.add({"energy", "trivial full-screen fill @1280x720", fill_ms, "ms", std::nullopt, false,
                "additive, the same scene colour"});
    report.add({"energy", "full-screen energy glow / trivial fill", glow_ms / fill_ms, "x", std::nullopt, false,
                "same target, same blending, same run"});
    report.add({"energy", "one closed form a pixel, full screen / trivial fill", one_ms / fill_ms, "x", std::nullopt,
                false,
                std::to_string(one_tiles) + " tiles, " + std::to_string(one_pairs) +
                    " pairs, no bloom: the floor of a per-pixel integral (" + fmt("%.2f", one_ms) + " ms)"});
    report.add({"energy", "full-screen energy pass / trivial fill", pass_ms / fill_ms, "x", 4.0, false,
                "glow + bloom; same target, same blending, same run"});
}

}  // namespace

void bench_energy(BenchReport& report, bool quick) {
    bench_accuracy(report, quick);
    bench_scaling(report, quick);
    bench_full_screen(report, quick);
}

}  // namespace game
