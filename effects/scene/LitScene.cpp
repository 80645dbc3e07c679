#include "effects/scene/LitScene.h"

#include <utility>
#include <vector>

#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/PipelineState.h"

namespace effects {

LitScene::LitScene(std::string label)
    : label_(std::move(label)), objects_(label_ + ".objects", {"scene/mesh.vert.glsl", "scene/mesh.frag.glsl"}) {}

const gl::Program& LitScene::depth(const Camera& camera) {
    if (!depth_) depth_ = gl::Program::from_files(label_ + ".depth", {"scene/mesh.vert.glsl", "scene/depth_only.frag.glsl"});
    depth_->set("u_view_proj", camera.view_proj);
    return *depth_;
}

LitScene::Programs LitScene::programs(const FrameContext& frame, const QualitySettings& quality, bool line_lights,
                                      bool normals, const Camera& camera) {
    if (!ground_) {
        const std::vector<std::string_view> files{"scene/mesh.vert.glsl", "scene/mesh.frag.glsl"};
        const std::string roads = "ROAD_COUNT " + std::to_string(frame.resources.geometry.ground_road_count());
        ground_.emplace(label_ + ".ground", files, std::vector<std::string>{"GROUND", roads});
        open_sky_ground_.emplace(label_ + ".ground.open_sky", files, std::vector<std::string>{"GROUND", roads, "OPEN_SKY 1"});
    }
    const gl::Program& objects = objects_.get(quality, line_lights, normals);
    const gl::Program& ground = ground_->get(quality, line_lights, normals);
    const gl::Program& open_sky_ground = open_sky_ground_->get(quality, line_lights, normals);
    for (const gl::Program* p : {&objects, &ground, &open_sky_ground}) {
        frame.lighting.apply(*p, frame.data);
        p->set("u_view_proj", camera.view_proj);
        p->set("u_eye", camera.eye);
    }
    for (const gl::Program* p : {&ground, &open_sky_ground}) {
        frame.resources.geometry.apply_ground(*p);
        p->set("u_wetness", frame.data.weather.road_wetness);
    }
    return {objects, ground, open_sky_ground};
}

void LitScene::draw_sky(const FrameData& data, const Camera& camera, bool normals) {
    std::optional<gl::Program>& sky = sky_[normals ? 1 : 0];
    if (!sky)
        sky = gl::Program::from_files(label_ + ".sky" + (normals ? ".normals" : ""),
                                      {"common/fullscreen.vert.glsl", "scene/sky.frag.glsl"},
                                      normals ? std::vector<std::string>{"SCENE_NORMALS"} : std::vector<std::string>{});
    gl::apply({.depth_test = true, .depth_func = GL_LEQUAL});
    sky->use();
    SceneLighting::apply_sky(*sky, data.sky);
    sky->set("u_inv_view_proj", camera.inv_view_proj);
    gl::bind_empty_vertex_array();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace effects
