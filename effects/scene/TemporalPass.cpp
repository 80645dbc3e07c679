#include "effects/scene/TemporalPass.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/PipelineState.h"
#include "effects/scene/SceneGeometry.h"
#include "effects/scene/ScreenRect.h"

namespace effects {

namespace {

float radical_inverse(uint64_t i, uint64_t base) {
    float result = 0.0f, digit = 1.0f / float(base);
    for (; i > 0; i /= base, digit /= float(base)) result += float(i % base) * digit;
    return result;
}

bool empty(glm::ivec4 rect) { return rect.z <= rect.x || rect.w <= rect.y; }

// The viewport less `hole` ({x0, y0, x1, y1}, x1/y1 exclusive; empty: none), as four
// bands (some empty): below, above, then left and right of it.
std::array<glm::ivec4, 4> rects_around(glm::ivec4 hole, int width, int height) {
    if (empty(hole)) return {glm::ivec4(0, 0, width, height), glm::ivec4(0), glm::ivec4(0), glm::ivec4(0)};
    return {glm::ivec4(0, 0, width, hole.y), glm::ivec4(0, hole.w, width, height), glm::ivec4(0, hole.y, hole.x, hole.w),
            glm::ivec4(hole.z, hole.y, width, hole.w)};
}

}  // namespace

TemporalBlend temporal_blend(float scene_scale) {
    constexpr float kSharpScale = 0.5f, kFloorScale = 0.35f;
    constexpr TemporalBlend kSharp{.jitter_spread = 0.5f, .current_weight = 0.3f};
    constexpr TemporalBlend kSmooth{.jitter_spread = 1.0f, .current_weight = 0.15f};
    const float t = std::clamp((kSharpScale - scene_scale) / (kSharpScale - kFloorScale), 0.0f, 1.0f);
    return {.jitter_spread = std::lerp(kSharp.jitter_spread, kSmooth.jitter_spread, t),
            .current_weight = std::lerp(kSharp.current_weight, kSmooth.current_weight, t)};
}

glm::vec2 temporal_jitter_px(uint64_t frame, float scene_scale) {
    const uint64_t i = frame % 8 + 1;  // Halton's point 0 is the pixel's corner
    return glm::vec2(radical_inverse(i, 2) - 0.5f, radical_inverse(i, 3) - 0.5f) * temporal_blend(scene_scale).jitter_spread;
}

glm::mat4 unjittered_view_proj(const Camera& camera) {
    return glm::translate(glm::mat4(1.0f), glm::vec3(-camera.jitter_ndc, 0.0f)) * camera.view_proj;
}

glm::mat4 history_reprojection(const glm::mat4& last_view_proj, const Camera& camera) {
    return last_view_proj * glm::inverse(unjittered_view_proj(camera));
}

TemporalPass::TemporalPass() {
    for (const bool from_hdr : {false, true})
        for (const bool vehicle : {false, true}) {
            std::vector<std::string> defines;
            if (from_hdr) defines.emplace_back("FROM_HDR");
            if (vehicle) defines.emplace_back("VEHICLE");
            programs_[from_hdr][vehicle] = gl::Program::from_files(
                std::string("temporal") + (from_hdr ? ".hdr" : "") + (vehicle ? ".vehicle" : ""),
                {"common/fullscreen.vert.glsl", "scene/temporal.frag.glsl"}, defines);
        }
}

void TemporalPass::render(const FrameContext& frame) {
    if (!frame.resources.quality.temporal) {
        has_history_ = false;
        return;
    }
    SceneTargets& t = frame.targets;
    t.start_history_frame();
    // A resize made new (empty) images: the first frame after it starts afresh.
    const bool history = has_history_ && history_generation_ == t.generation();
    const Camera& camera = frame.camera;
    const TemporalBlend blend = temporal_blend(scene_scale(t, frame.output));
    const glm::mat4 unjittered = unjittered_view_proj(camera);
    // The vehicle nearest the eye (the one the camera rides or follows) moves with its
    // pose, not with the world: its pixels' last place is through its last pose.
    const bool car_nearer = glm::distance(frame.poses.car.position, camera.eye) <=
                            glm::distance(frame.poses.boat.position, camera.eye);
    const sim::Pose& ridden = car_nearer ? frame.poses.car : frame.poses.boat;
    const glm::mat4 vehicle = ridden.matrix();
    const glm::mat4 last_vehicle = history ? last_vehicle_ : vehicle;
    // The pixels the vehicle can cover: only they need its candidate (a second history
    // fetch a pixel).
    const SceneDesc& desc = frame.resources.desc;
    const int model = car_nearer ? desc.car_model : desc.boat_model;
    glm::ivec4 vehicle_rect(0);
    if (model >= 0) {
        const auto [lo, hi] = world_box(desc.models[size_t(model)], vehicle);
        vehicle_rect = screen_rect_of_box(camera.view_proj, camera.near_m, lo, hi, t.width(), t.height(), 2);
    }

    t.history_fbo().bind();
    glViewport(0, 0, t.width(), t.height());
    gl::PipelineScope state({.scissor = true});
    const bool from_hdr = tonemapped_by_temporal(frame.resources.quality);
    const gl::Texture& current = from_hdr ? t.colour() : frame.resources.quality.antialias ? t.antialiased() : t.display();
    current.bind(0);
    t.previous_history().bind(1);
    t.depth().bind(2);
    gl::bind_empty_vertex_array();
    for (const bool with_vehicle : {false, true}) {
        const gl::Program& program = programs_[from_hdr][with_vehicle];
        program.use();
        program.set("u_current", 0);
        program.set("u_history", 1);
        program.set("u_depth", 2);
        if (from_hdr) program.set("u_exposure", frame.resources.exposure);
        // Where the pixel's point was in the last frame's view: as a still part of the
        // world, or as a point on the vehicle; what else moves (thrown objects, water)
        // is left to the clamp.
        program.set("u_reproject", history_reprojection(last_view_proj_, camera));
        if (with_vehicle)
            program.set("u_reproject_vehicle", history_reprojection(last_view_proj_ * last_vehicle * glm::inverse(vehicle), camera));
        program.set("u_current_weight", history ? blend.current_weight : 1.0f);
        auto draw_in = [](glm::ivec4 r) {
            if (empty(r)) return;
            glScissor(r.x, r.y, r.z - r.x, r.w - r.y);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        };
        if (with_vehicle) draw_in(vehicle_rect);
        else
            for (const glm::ivec4& r : rects_around(vehicle_rect, t.width(), t.height())) draw_in(r);
    }

    last_view_proj_ = unjittered;
    last_vehicle_ = vehicle;
    has_history_ = true;
    history_generation_ = t.generation();
}

}  // namespace effects
