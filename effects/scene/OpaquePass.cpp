#include "effects/scene/OpaquePass.h"

#include <string>
#include <vector>

#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/PipelineState.h"

namespace effects {

OpaquePass::OpaquePass()
    : objects_("opaque.objects", {"scene/mesh.vert.glsl", "scene/mesh.frag.glsl"}),
      sky_(gl::Program::from_files("opaque.sky", {"common/fullscreen.vert.glsl", "scene/sky.frag.glsl"})) {}

void OpaquePass::render(const FrameContext& frame) {
    SceneTargets& t = frame.scene.targets;
    glBindFramebuffer(GL_FRAMEBUFFER, t.scene().id());
    glViewport(0, 0, t.width(), t.height());
    gl::PipelineScope state({.depth_test = true, .depth_write = true, .cull_back_faces = true});
    const float clear_colour[4] = {0, 0, 0, 1}, clear_normal[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, clear_colour);
    glClearBufferfv(GL_COLOR, 1, clear_normal);
    glClear(GL_DEPTH_BUFFER_BIT);

    const bool line_lights = frame.scene.lighting.has_line_lights();
    if (!ground_)
        ground_.emplace("opaque.ground", std::vector<std::string_view>{"scene/mesh.vert.glsl", "scene/mesh.frag.glsl"},
                        std::vector<std::string>{"GROUND", "ROAD_COUNT " +
                                                               std::to_string(frame.scene.geometry.ground_road_count())});
    const SceneLighting& lighting = frame.scene.lighting;
    const Frustum view(frame.camera.view_proj);
    // With beams flying, what they reach is drawn with the line-light sum and the rest
    // without it: the sum is a lit pixel's costliest loop, and a beam lights a few
    // metres around it.
    for (const bool lit : {true, false}) {
        if (lit && !line_lights) continue;
        const gl::Program& objects = objects_.get(frame.scene.quality, lit);
        const gl::Program& ground = ground_->get(frame.scene.quality, lit);
        for (const gl::Program* p : {&objects, &ground}) {
            lighting.apply(*p, frame.data);
            p->set("u_view_proj", frame.camera.view_proj);
            p->set("u_eye", frame.camera.eye);
        }
        frame.scene.geometry.apply_ground(ground);
        ground.set("u_wetness", frame.data.weather.road_wetness);
        SceneGeometry::Select select;
        if (line_lights)
            select = [&lighting, lit](glm::vec3 lo, glm::vec3 hi) { return lighting.line_lights_reach(lo, hi) == lit; };
        frame.scene.geometry.draw(objects, ground, frame.poses, SceneGeometry::Use::Shading, view, select);
    }

    // Sky last, only where nothing was drawn: the far plane passes GL_LEQUAL.
    gl::apply({.depth_test = true, .depth_func = GL_LEQUAL});
    sky_.use();
    SceneLighting::apply_sky(sky_, frame.data.sky);
    sky_.set("u_inv_view_proj", frame.camera.inv_view_proj);
    gl::bind_empty_vertex_array();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace effects
