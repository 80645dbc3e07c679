#include "effects/scene/EnvironmentPass.h"

#include "effects/gl/PipelineState.h"

namespace effects {

EnvironmentPass::EnvironmentPass()
    : program_(gl::Program::from_files("environment", {"common/fullscreen.vert.glsl", "scene/env_cube.frag.glsl"})),
      fbo_(gl::Framebuffer::create("environment")) {}

void EnvironmentPass::render(const FrameContext& frame) {
    SceneLighting& lighting = frame.lighting;
    if (valid_ && filled_ == frame.data.sky) return;
    // Face order +X -X +Y -Y +Z -Z with the GL cube map conventions.
    const glm::vec3 fwd[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::vec3 right[6] = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {-1, 0, 0}};
    const glm::vec3 up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    program_.use();
    SceneLighting::apply_sky(program_, frame.data.sky);
    gl::PipelineScope state(gl::kFullScreen);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    int size = lighting.env_cube.width();
    glViewport(0, 0, size, size);
    gl::bind_empty_vertex_array();
    for (int face = 0; face < 6; ++face) {
        fbo_.attach_colour_layer(0, lighting.env_cube, face);
        fbo_.set_draw_buffers({0});
        program_.set("u_face_forward", fwd[face]);
        program_.set("u_face_right", right[face]);
        program_.set("u_face_up", up[face]);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    lighting.env_cube.generate_mipmaps();
    filled_ = frame.data.sky;
    valid_ = true;
}

}  // namespace effects
