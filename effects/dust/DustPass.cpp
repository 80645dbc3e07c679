#include "effects/dust/DustPass.h"

#include "effects/gl/DrawCount.h"
#include "effects/gl/PipelineState.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace effects {

namespace {
constexpr GLuint kFibreUnit = 0, kLuminanceUnit = 1;

// Whether a box can be seen: not all of its corners beyond one clip plane.
bool in_view(const glm::mat4& view_proj, glm::vec3 lo, glm::vec3 hi) {
    glm::vec4 c[8];
    for (int k = 0; k < 8; ++k)
        c[k] = view_proj * glm::vec4(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z, 1.0f);
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            bool all_out = true;
            for (const glm::vec4& v : c) all_out = all_out && side * v[axis] > v.w;
            if (all_out) return false;
        }
    return true;
}
}  // namespace

DustPass::DustPass()
    : light_(gl::Program::from_files("dust.light", {"dust/light.comp.glsl"})),
      shell_(gl::Program::from_files("dust.shell", {"dust/shell.vert.glsl", "dust/shell.frag.glsl"})),
      fin_(gl::Program::from_files("dust.fin", {"dust/fin.vert.glsl", "dust/shell.frag.glsl"})) {}

void DustPass::register_params(ParamRegistry& params) {
    params.add("dust", "max shells", &lod_.max_shells, 1, 32);
    params.add("dust", "min shells", &lod_.min_shells, 1, 16);
    params.add("dust", "full detail (m)", &lod_.full_detail_m, 0.5f, 20.0f);
    params.add("dust", "fin min height (px)", &lod_.fin_min_px, 0.0f, 16.0f);
    params.add("dust", "coarse from (m)", &lod_.coarse_from_m, 0.0f, 60.0f);
    params.add("dust", "fins", &fins_);
}

int DustPass::shells_at(float distance_m) const {
    float d = std::max(distance_m, lod_.full_detail_m);
    int n = int(std::lround(float(lod_.max_shells) * lod_.full_detail_m / d));
    return std::clamp(n, std::min(lod_.min_shells, lod_.max_shells), lod_.max_shells);
}

int DustPass::level_at(float distance_m) const { return distance_m >= lod_.coarse_from_m ? 1 : 0; }

const FibreTexture& DustPass::fibres_for(sim::DustKind kind, const FibreDirections& directions) {
    auto& slot = fibres_[size_t(kind)];
    if (!slot) {
        if (directions.empty())
            throw std::invalid_argument("dust: the level has dusty props but no fibre directions (dust.fibre_image)");
        slot = std::make_unique<FibreTexture>(grow_fibres(directions, dust_look(kind).growth), sim::dust_kind_name(kind));
    }
    return *slot;
}

void DustPass::render(const FrameContext& frame) {
    const sim::DustField* field = frame.world.find<sim::DustField>();
    if (!field || field->surface().props().empty()) return;
    geometry_.update(*field, frame.world.level().dust, frame.resources.desc);
    if (geometry_.dusty_triangles() == 0) return;

    const SceneTargets& t = frame.targets;
    const Camera& cam = frame.camera;
    glBindFramebuffer(GL_FRAMEBUFFER, t.hdr().id());
    glViewport(0, 0, t.width(), t.height());
    // Shells hug the surface where the dust is thin: an offset keeps them in front of it.
    gl::PipelineScope state({.depth_test = true,
                             .depth_write = true,
                             .depth_func = GL_LEQUAL,
                             .offset_factor = -1.0f,
                             .offset_units = -2.0f});

    // The props in view, lit once per vertex of the level they are drawn at.
    const auto& props = field->surface().props();
    std::vector<bool> visible(props.size());
    std::vector<float> distance(props.size());
    std::vector<const DustDrawRange*> range(props.size());
    frame.lighting.apply(light_, frame.data);
    light_.set("u_eye", cam.eye);
    light_.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, geometry_.vertices().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, geometry_.vertex_light().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, geometry_.sky_exposure().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, geometry_.lit_vertices().id());
    for (size_t i = 0; i < props.size(); ++i) {
        const float pad = dust_look(props[i].kind).height_m;
        distance[i] = glm::length(cam.eye - glm::clamp(cam.eye, props[i].bounds.min, props[i].bounds.max));
        range[i] = &geometry_.ranges(level_at(distance[i]))[i];
        visible[i] = range[i]->shell_index_count > 0 &&
                     in_view(cam.view_proj, props[i].bounds.min - pad, props[i].bounds.max + pad);
        if (!visible[i]) continue;
        light_.set("u_first", range[i]->first_lit);
        light_.set("u_count", range[i]->lit_count);
        glDispatchCompute((range[i]->lit_count + 63) / 64, 1, 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    for (const gl::Program* p : {&shell_, &fin_}) {
        p->set("u_view_proj", cam.view_proj);
        p->set("u_eye", cam.eye);
        p->set("u_fibres", int(kFibreUnit));
        p->set("u_luminance", int(kLuminanceUnit));
        p->set("u_threshold", kFibreThreshold);
    }
    for (size_t i = 0; i < props.size(); ++i) {
        if (!visible[i]) continue;
        const sim::DustPropRange& prop = props[i];
        const DustDrawRange& r = *range[i];
        const DustLook look = dust_look(prop.kind);
        const FibreTexture& fibres = fibres_for(prop.kind, frame.resources.desc.fibre_directions);
        fibres.bind(kFibreUnit, kLuminanceUnit);
        const int shells = std::min(shells_at(distance[i]), frame.resources.quality.dust_max_shells);
        for (const gl::Program* p : {&shell_, &fin_}) {
            p->set("u_height_m", look.height_m);
            p->set("u_tile_m", look.tile_m);
            p->set("u_bumpiness", look.bumpiness);
            p->set("u_colour", look.colour);
            p->set("u_deep_colour", look.deep_colour);
            p->set("u_layers", fibres.layers());
            p->set("u_shells", shells);
        }
        // Shells shells..1 from the top down, then the film on the surface.
        shell_.use();
        shell_.set("u_fin", 0);
        geometry_.shells().bind();
        gl::count_draw(r.shell_index_count, shells + 1);
        glDrawElementsInstanced(GL_TRIANGLES, r.shell_index_count, GL_UNSIGNED_INT,
                                reinterpret_cast<const void*>(r.first_shell_index * sizeof(uint32_t)), shells + 1);
        // The stack's height on screen at the prop's nearest point.
        const float stack_px = look.height_m * cam.proj[1][1] * 0.5f * float(t.height()) / std::max(distance[i], 1e-3f);
        if (r.fin_index_count > 0 && fins_at(stack_px)) {
            fin_.use();
            fin_.set("u_fin", 1);
            geometry_.fins().bind();
            gl::count_draw(r.fin_index_count);
            glDrawElements(GL_TRIANGLES, r.fin_index_count, GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(r.first_fin_index * sizeof(uint32_t)));
        }
    }
}

}  // namespace effects
