#include "effects/scene/MirrorPass.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "effects/gl/PipelineState.h"
#include "sim/player/Player.h"

namespace effects {

namespace {
// The view's width across the glass. A flat mirror a hand's width wide at arm's length
// shows about 25 degrees behind; a little more reads better on a screen.
constexpr float kFieldAcrossDeg = 36.0f;
// Beyond this the picture shows the sky: the fog has half hidden what lies further, and
// a far plane this near leaves most of the level's terrain and props to the culling.
constexpr float kFarM = 150.0f;
const glm::vec4 kSeaTint{0.018f, 0.045f, 0.05f, 1.0f};  // the sea, flat: a dark green-grey
}  // namespace

// Where the mirror is this frame and the camera that looks back out of it.
struct MirrorPass::View {
    glm::mat4 body{1.0f};
    glm::vec3 centre{0.0f}, across{0.0f}, up{0.0f};  // world space, axes unit
    Camera camera;
};

MirrorPass::MirrorPass()
    : scene_("mirror"),
      glass_program_(gl::Program::from_files("mirror.glass", {"scene/mesh.vert.glsl", "scene/mirror_glass.frag.glsl"})) {}

std::optional<MirrorPass::Glass> MirrorPass::find_glass(const SceneDesc& desc) {
    if (desc.car_model < 0) return std::nullopt;
    for (const MeshData& m : desc.models[size_t(desc.car_model)].meshes) {
        if (m.name != "mirror_glass" || m.vertices.empty()) continue;
        glm::vec3 lo = m.vertices[0].position, hi = lo;
        for (const MeshVertex& v : m.vertices) {
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
        }
        Glass g;
        g.centre = 0.5f * (lo + hi);
        g.normal = glm::normalize(m.vertices[0].normal);
        g.across = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), g.normal));
        g.up = glm::cross(g.normal, g.across);
        for (const MeshVertex& v : m.vertices) {
            g.half_width = std::max(g.half_width, std::fabs(glm::dot(v.position - g.centre, g.across)));
            g.half_height = std::max(g.half_height, std::fabs(glm::dot(v.position - g.centre, g.up)));
        }
        if (g.half_width <= 0.0f || g.half_height <= 0.0f) return std::nullopt;
        return g;
    }
    return std::nullopt;
}

void MirrorPass::render(const FrameContext& frame) {
    drawn_ = false;
    const int width = frame.resources.quality.mirror_width;
    if (width <= 0) return;
    const auto* player = frame.world.find<sim::Player>();
    if (!player || player->vehicle() != sim::Vehicle::Car || player->view() != sim::ViewMode::Driver) return;
    if (!looked_up_) {
        looked_up_ = true;
        glass_ = find_glass(frame.resources.desc);
        if (glass_) {
            Model m;
            for (const MeshData& mesh : frame.resources.desc.models[size_t(frame.resources.desc.car_model)].meshes)
                if (mesh.name == "mirror_glass") m.meshes.push_back(mesh);
            glass_model_ = std::make_unique<GpuModel>(m);
        }
    }
    if (!glass_) return;
    const Glass& g = *glass_;

    // The glass in the world, and whether the driver's view holds it.
    View v;
    v.body = frame.poses.car.matrix();
    const glm::mat3 turn(v.body);
    v.centre = glm::vec3(v.body * glm::vec4(g.centre, 1.0f));
    v.across = turn * g.across;
    v.up = turn * g.up;
    const glm::vec3 reach = glm::abs(v.across) * g.half_width + glm::abs(v.up) * g.half_height;
    if (Frustum(frame.camera.view_proj).outside(v.centre - reach, v.centre + reach)) return;

    // From the glass straight back out of the car, the picture as wide as the glass.
    const float aspect = g.half_width / g.half_height;
    sim::CameraView look;
    look.eye = v.centre;
    look.target = v.centre + turn * g.normal;
    look.up = v.up;
    look.fov_y_deg = glm::degrees(2.0f * std::atan(std::tan(glm::radians(0.5f * kFieldAcrossDeg)) / aspect));
    v.camera = make_camera(look, aspect);
    v.camera.far_m = kFarM;
    v.camera.proj = glm::perspective(glm::radians(look.fov_y_deg), aspect, v.camera.near_m, v.camera.far_m);
    v.camera.view_proj = v.camera.proj * v.camera.view;
    v.camera.inv_view_proj = glm::inverse(v.camera.view_proj);

    const int height = std::max(1, width / 4);
    if (width != width_ || height != height_) {
        width_ = width;
        height_ = height;
        colour_ = gl::Texture::create_2d("mirror.colour", GL_RGBA16F, width, height);
        colour_.set_filter(GL_LINEAR, GL_LINEAR);
        colour_.set_wrap(GL_CLAMP_TO_EDGE);
        depth_ = gl::Texture::create_2d("mirror.depth", GL_DEPTH_COMPONENT32F, width, height);
        fbo_ = gl::Framebuffer::create("mirror");
        fbo_.attach_colour(0, colour_);
        fbo_.attach_depth(depth_);
        fbo_.set_draw_buffers({0});
        fbo_.check_complete();
    }
    draw_behind(frame, v);
    draw_glass(frame, v);
    drawn_ = true;
}

void MirrorPass::draw_behind(const FrameContext& frame, const View& v) {
    fbo_.bind();
    glViewport(0, 0, width_, height_);
    gl::PipelineScope state({.depth_test = true, .depth_write = true, .cull_back_faces = true});
    const float clear_colour[4] = {0, 0, 0, 1};
    glClearBufferfv(GL_COLOR, 0, clear_colour);
    glClear(GL_DEPTH_BUFFER_BIT);

    // Shaded as the low preset shades, one shadow tap and no reflections, and without the
    // energy beams' light: the picture is small and seen in passing.
    QualitySettings cheap = frame.resources.quality;
    cheap.soft_shadows = false;
    cheap.env_reflection = false;
    cheap.ground_detail = false;
    const LitScene::Programs p = scene_.programs(frame, cheap, false, false, v.camera);
    // The car is left out: the mirror looks out of it, through where its rear window is.
    const Frustum behind(v.camera.view_proj);
    frame.resources.geometry.draw(p.objects, p.ground, frame.poses, SceneGeometry::Use::Shading, behind, {},
                              SceneGeometry::Car::LeftOut, std::nullopt, &p.open_sky_ground);

    p.objects.use();
    p.objects.set("u_model", glm::mat4(1.0f));
    p.objects.set("u_normal_matrix", glm::mat3(1.0f));
    p.objects.set("u_tint", kSeaTint);
    frame.resources.geometry.sea().draw(p.objects, false);
    p.objects.set("u_tint", glm::vec4(1.0f));

    scene_.draw_sky(frame.data, v.camera, false);
}

void MirrorPass::draw_glass(const FrameContext& frame, const View& v) {
    // The glass again, over itself as the opaque pass drew it: only its own pixels, and
    // only their colour (the opaque pass wrote their normals, when drawn).
    SceneTargets& t = frame.targets;
    glBindFramebuffer(GL_FRAMEBUFFER, t.hdr().id());
    glViewport(0, 0, t.width(), t.height());
    gl::PipelineScope state({.depth_test = true, .depth_func = GL_LEQUAL, .offset_factor = -1.0f, .offset_units = -1.0f});
    if (t.writes_normals()) glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glass_program_.use();
    glass_program_.set("u_view_proj", frame.camera.view_proj);
    glass_program_.set("u_model", v.body);
    glass_program_.set("u_normal_matrix", glm::mat3(glm::transpose(glm::inverse(v.body))));
    glass_program_.set("u_centre", v.centre);
    glass_program_.set("u_across", v.across / glass_->half_width);
    glass_program_.set("u_up", v.up / glass_->half_height);
    colour_.bind(0);
    glass_program_.set("u_picture", 0);
    glass_model_->draw(glass_program_, true);
}

}  // namespace effects
