#include "game/bench/DustBench.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "effects/dust/DustLook.h"
#include "effects/dust/DustPass.h"
#include "effects/dust/FibreTexture.h"
#include "effects/dust/FibreVolume.h"
#include "effects/dust/SkyExposure.h"
#include "effects/gl/PipelineState.h"
#include "effects/gl/Program.h"
#include "game/bench/BenchSupport.h"
#include "game/level/LevelLoader.h"
#include "game/stage/RenderStage.h"
#include "sim/dust/DustAccumulation.h"
#include "sim/dust/DustField.h"

namespace game {

namespace {

using Clock = std::chrono::steady_clock;

// The scene props that are the dusty ones: their placed model bounds match a dusty
// prop's bounds (the sim knows them only as triangles).
std::vector<size_t> dusty_scene_props(const effects::SceneDesc& scene, const sim::DustField& field) {
    std::vector<size_t> out;
    for (size_t i = 0; i < scene.props.size(); ++i) {
        const effects::PropInstance& inst = scene.props[i];
        glm::vec3 lo(INFINITY), hi(-INFINITY);
        for (const effects::MeshData& m : scene.models[size_t(inst.model)].meshes)
            for (const effects::MeshVertex& v : m.vertices) {
                glm::vec3 p(inst.transform * glm::vec4(v.position, 1.0f));
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
        for (const sim::DustPropRange& d : field.surface().props())
            if (glm::length(lo - d.bounds.min) < 1e-3f && glm::length(hi - d.bounds.max) < 1e-3f) {
                out.push_back(i);
                break;
            }
    }
    return out;
}

}  // namespace

void bench_dust_cpu(BenchReport& report, bool quick) {
    const LoadedLevel level = load_level("harbour");
    const int reps = quick ? 1 : 3;
    for (int k = 0; k < sim::kDustKindCount; ++k) {
        const auto kind = sim::DustKind(k);
        const effects::DustLook look = effects::dust_look(kind);
        double grow_ms = 0.0, mip_ms = 0.0;
        for (int r = 0; r < reps; ++r) {
            auto start = Clock::now();
            effects::FibreVolume v = effects::grow_fibres(level.scene.fibre_directions, look.growth);
            grow_ms += ms_since(start);
            start = Clock::now();
            for (int l = 0; l < v.layers; ++l) effects::fibre_mips(v, l);
            mip_ms += ms_since(start);
        }
        const std::string what = std::string(sim::dust_kind_name(kind));
        report.add({"dust", "fibre growth, " + what + " preset", grow_ms / reps, "ms", std::nullopt, false,
                    std::to_string(look.growth.fibres) + " fibres of " + std::to_string(look.growth.steps) + " steps, " +
                        std::to_string(look.growth.size) + "^2 x " + std::to_string(look.growth.layers) + " layers"});
        report.add({"dust", "fibre mip levels, " + what + " preset", mip_ms / reps, "ms", std::nullopt, false,
                    "coverage-preserving, all layers"});
    }

    const sim::DustDesc& desc = level.sim.dust;
    auto start = Clock::now();
    sim::DustSurface surface(desc.props, desc.sample_spacing_m);
    report.add({"dust", "tessellation of the dusty props", ms_since(start), "ms", std::nullopt, false,
                std::to_string(surface.positions().size()) + " vertices at " + fmt("%.2f m", desc.sample_spacing_m)});
    start = Clock::now();
    effects::sky_exposure(surface, level.scene);
    report.add({"dust", "sky exposure of the dusty props", ms_since(start), "ms", std::nullopt, false,
                "once, at the first dust frame: 5 maps per prop of every scene prop"});
    std::vector<float> amounts(surface.positions().size());
    for (size_t p = 0; p < surface.props().size(); ++p) {
        start = Clock::now();
        for (int r = 0; r < reps; ++r) sim::accumulate_dust(surface, p, desc.props, desc, amounts);
        const sim::DustPropRange& prop = surface.props()[p];
        report.add({"dust", "accumulation " + prop.name, ms_since(start) / reps, "ms", std::nullopt, false,
                    std::to_string(prop.vertex_count) + " vertices, " + std::to_string(desc.sources_per_prop) +
                        " shadow maps of " + std::to_string(sim::kSourceMapSize) + "^2"});
    }
}

void bench_dust_render(BenchReport& report, int width, int height, bool quick, DustBenchView where) {
    // The dust's lighting (environment, shadow, sky occlusion) and the dust pass.
    RenderStage stage("harbour", {.width = width,
                                  .height = height,
                                  .passes = effects::PassSet::of({"environment", "shadow", "sky occlusion", "dust"}),
                                  .environment_size = 64});
    const sim::DustField* field = stage.world().find<sim::DustField>();
    if (!field) return;
    const effects::RenderResources& resources = stage.resources();
    const effects::SceneDesc& desc = resources.desc;
    sim::CameraView view;
    if (where == DustBenchView::Warehouse) {  // inside the door, over the crates, the shelf and the old car
        view.eye = {-39.0f, 4.0f, -36.5f};
        view.target = {-41.0f, 1.8f, -45.5f};
        view.fov_y_deg = 60.0f;
    } else {  // about 2 m from the crates: every shell and the fins
        view.eye = {-47.6f, 3.6f, -44.0f};
        view.target = {-49.6f, 2.3f, -46.0f};
        view.fov_y_deg = 50.0f;
    }
    effects::Camera camera = effects::make_camera(view, float(width) / float(height));
    stage.draw(camera, {.skip = effects::PassSet::of({"dust"})});
    const effects::FrameContext frame = stage.context(camera);
    effects::DustPass& dust = stage.pass<effects::DustPass>();

    const std::vector<size_t> props = dusty_scene_props(desc, *field);
    std::vector<std::unique_ptr<effects::GpuModel>> models;
    for (size_t i : props) models.push_back(std::make_unique<effects::GpuModel>(desc.models[size_t(desc.props[i].model)]));
    effects::gl::Program mesh = effects::gl::Program::from_files("bench.mesh", {"scene/mesh.vert.glsl", "scene/mesh.frag.glsl"});
    auto draw_props = [&] {
        glBindFramebuffer(GL_FRAMEBUFFER, stage.targets().hdr().id());
        glViewport(0, 0, width, height);
        effects::gl::PipelineScope state({.depth_test = true, .depth_write = true, .cull_back_faces = true});
        mesh.use();
        stage.lighting().apply(mesh, frame.data);
        mesh.set("u_view_proj", camera.view_proj);
        mesh.set("u_eye", camera.eye);
        mesh.set("u_surface", 0);
        mesh.set("u_tint", glm::vec4(1.0f));
        for (size_t k = 0; k < props.size(); ++k) {
            const glm::mat4& m = desc.props[props[k]].transform;
            mesh.set("u_model", m);
            mesh.set("u_normal_matrix", glm::mat3(glm::transpose(glm::inverse(m))));
            models[k]->draw(mesh, false);
        }
    };
    auto clear = [&] {
        glBindFramebuffer(GL_FRAMEBUFFER, stage.targets().hdr().id());
        const float black[4] = {0, 0, 0, 1};
        glClearBufferfv(GL_COLOR, 0, black);
        glClear(GL_DEPTH_BUFFER_BIT);
    };
    // Warm up (shader compile, fibre textures, buffers), then alternate so both see
    // the same machine state.
    clear();
    draw_props();
    dust.render(frame);
    glFinish();
    const int frames = quick ? 4 : 12;
    double props_ms = 0.0, dust_ms = 0.0;
    for (int f = 0; f < frames; ++f) {
        clear();
        glFinish();
        auto start = Clock::now();
        draw_props();
        glFinish();
        props_ms += ms_since(start);
        start = Clock::now();
        dust.render(frame);
        glFinish();
        dust_ms += ms_since(start);
    }
    props_ms /= frames;
    dust_ms /= frames;
    const std::string res = std::string(where == DustBenchView::CloseUp ? "close-up " : "") + "@" +
                            std::to_string(width) + "x" + std::to_string(height);
    const effects::DustGeometry& g = dust.geometry();
    const std::string note = std::to_string(props.size()) + " props, " + std::to_string(g.dusty_triangles(0)) + " dusty triangles, " +
                             std::to_string(g.fin_quads(0)) + " fins (coarse level " + std::to_string(g.dusty_triangles(1)) + ", " +
                             std::to_string(g.fin_quads(1)) + ")" +
                             (where == DustBenchView::CloseUp ? ", " + std::to_string(dust.shells_at(2.0f)) + " shells near" : "");
    report.add({"dust", "warehouse props without dust " + res, props_ms, "ms", std::nullopt, false, note});
    report.add({"dust", "dust pass (shells + fins) " + res, dust_ms, "ms", std::nullopt, false, note});
    // The issue's target is the warehouse view at 1280x720; the close-up (12 shells over
    // most of the screen) is the worst case, reported beside it.
    const bool targeted = width >= 1280 && where != DustBenchView::CloseUp;
    report.add({"dust", "dusty props / props without dust " + res, (props_ms + dust_ms) / props_ms, "x",
                targeted ? std::optional<double>(2.0) : std::nullopt, false,
                where == DustBenchView::CloseUp ? "profile mode: glFinish around each; worst case, no target"
                                                : "profile mode: glFinish around each"});
}

}  // namespace game
