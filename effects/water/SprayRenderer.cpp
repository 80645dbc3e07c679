#include "effects/water/SprayRenderer.h"

#include "effects/gl/PipelineState.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace effects {

SprayRenderer::SprayRenderer()
    : program_(gl::Program::from_files("water.spray", {"water/spray.vert.glsl", "water/spray.frag.glsl"})),
      vao_(gl::VertexArray::create("water.spray")) {
    vao_.attribute(0, 0, 4, GL_FLOAT, 0);
    vao_.binding_divisor(0, 1);
}

void SprayRenderer::draw(const FrameContext& frame, std::span<const SprayDrop> drops, const SprayLook& look) {
    if (drops.empty()) return;
    const size_t bytes = drops.size_bytes();
    if (instances_.id() == 0 || size_t(instances_.size()) < bytes) {
        size_t capacity = instances_.id() == 0 ? 1024 * sizeof(SprayDrop) : size_t(instances_.size());
        while (capacity < bytes) capacity *= 2;
        instances_ = gl::Buffer::create("water.spray.instances", GLsizeiptr(capacity));
        vao_.vertex_buffer(0, instances_, 0, sizeof(SprayDrop));
    }
    instances_.update<SprayDrop>(0, drops);

    const Camera& cam = frame.camera;
    const glm::mat4 inv_view = glm::inverse(cam.view);
    const SceneTargets& t = frame.targets;
    if (generation_ != t.generation()) {
        fbo_ = gl::Framebuffer::create("water.spray");
        fbo_.attach_colour(0, t.colour());
        fbo_.attach_depth(t.depth());
        fbo_.check_complete();
        generation_ = t.generation();
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, t.width(), t.height());
    program_.use();
    frame.lighting.apply(program_, frame.data);
    program_.set("u_view_proj", cam.view_proj);
    program_.set("u_eye", cam.eye);
    program_.set("u_cam_right", glm::vec3(inv_view[0]));
    program_.set("u_cam_up", glm::vec3(inv_view[1]));
    // World size of one pixel one metre from the eye.
    program_.set("u_pixel_m", 2.0f / (cam.proj[1][1] * float(t.height())));
    program_.set("u_min_pixels", look.min_pixels);
    program_.set("u_blur_m", look.blur_m);
    program_.set("u_opacity", look.opacity);

    // Premultiplied "over": drops are all nearly the same colour, so order hardly
    // shows and no sort is needed. The scene's alpha stays as it is. Depth-tested, not
    // written.
    gl::apply({.depth_test = true, .blend = gl::kPremultipliedOver});
    vao_.bind();
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(drops.size()));
}

}  // namespace effects
