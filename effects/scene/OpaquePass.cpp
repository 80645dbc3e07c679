#include "effects/scene/OpaquePass.h"

#include <glm/common.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>

#include "effects/gl/PipelineState.h"

namespace effects {

namespace {

// Whether the eye is within a vehicle's bounds (its model's box, a little larger, around
// its pose): the driver's seat, the boat's helm.
bool eye_in_a_vehicle(const FrameContext& frame) {
    const SceneDesc& desc = frame.resources.desc;
    auto inside = [&](int model, const sim::Pose& pose) {
        if (model < 0) return false;
        const Model& m = desc.models[size_t(model)];
        const glm::vec3 eye(glm::inverse(pose.matrix()) * glm::vec4(frame.camera.eye, 1.0f));
        return glm::all(glm::greaterThanEqual(eye, m.bounds_min - 0.5f)) &&
               glm::all(glm::lessThanEqual(eye, m.bounds_max + 0.5f));
    };
    return inside(desc.car_model, frame.poses.car) || inside(desc.boat_model, frame.poses.boat);
}

}  // namespace

OpaquePass::OpaquePass() : scene_("opaque") {}

void OpaquePass::render(const FrameContext& frame) {
    SceneTargets& t = frame.targets;
    glBindFramebuffer(GL_FRAMEBUFFER, t.hdr().id());
    glViewport(0, 0, t.width(), t.height());
    gl::PipelineScope state({.depth_test = true, .depth_write = true, .cull_back_faces = true});
    const bool normals = t.writes_normals();
    const float clear_colour[4] = {0, 0, 0, 1}, clear_normal[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, clear_colour);
    if (normals) glClearBufferfv(GL_COLOR, 1, clear_normal);
    glClear(GL_DEPTH_BUFFER_BIT);

    const std::vector<LineLight>& lights = frame.data.line_lights;
    const bool line_lights = !lights.empty();
    const Frustum view(frame.camera.view_proj);
    // The vehicles' depth first: from the driver's seat the car's parts cover each other
    // (the body behind the dashboard, the headliner behind the visors), and a part
    // hidden by one drawn later was shaded for nothing. Laid a little behind (the
    // offset), so the nearest part still passes GL_LESS when shaded and ties between
    // parts, or with a prop or the ground, go as they went without it: the same image,
    // each vehicle pixel shaded about once.
    // Only from inside a vehicle: seen from outside, its parts hardly cover each other,
    // and the depth draws (a draw a part) would cost more than they spare.
    const gl::PipelineState shading{.depth_test = true, .depth_write = true, .cull_back_faces = true};
    if (eye_in_a_vehicle(frame)) {
        gl::PipelineState vehicles_depth = shading;
        vehicles_depth.colour_write = false;
        vehicles_depth.offset_factor = 1.0f;
        vehicles_depth.offset_units = 1.0f;
        gl::apply(vehicles_depth);
        const gl::Program& depth = scene_.depth(frame.camera);
        frame.resources.geometry.draw(depth, depth, frame.poses, SceneGeometry::Use::MovingShadowCasters, view, {},
                                      SceneGeometry::Car::Drawn, frame.camera.eye);
    }
    gl::apply(shading);
    // With beams flying, what they reach is drawn with the line-light sum and the rest
    // without it: the sum is a lit pixel's costliest loop, and a beam lights a few
    // metres around it.
    for (const bool lit : {true, false}) {
        if (lit && !line_lights) continue;
        const LitScene::Programs p = scene_.programs(frame, frame.resources.quality, lit, normals, frame.camera);
        SceneGeometry::Select select;
        if (line_lights)
            select = [&lights, lit](glm::vec3 lo, glm::vec3 hi) { return line_lights_reach(lights, lo, hi) == lit; };
        frame.resources.geometry.draw(p.objects, p.ground, frame.poses, SceneGeometry::Use::Shading, view, select,
                                      SceneGeometry::Car::Drawn, frame.camera.eye, &p.open_sky_ground);
    }

    // Sky last, only where nothing was drawn.
    scene_.draw_sky(frame.data, frame.camera, normals);
}

}  // namespace effects
