#include "effects/energy/EnergyProbe.h"

#include "effects/gl/PipelineState.h"

#include <stdexcept>
#include <string>

namespace effects {

EnergyProbe::EnergyProbe(int width, int height)
    : width_(width),
      height_(height),
      depth_(gl::Texture::create_2d("energy_probe.depth", GL_DEPTH_COMPONENT32F, width, height)),
      colour_(gl::Texture::create_2d("energy_probe.colour", GL_RGBA32F, width, height)),
      fbo_(gl::Framebuffer::create("energy_probe")) {
    depth_.set_filter(GL_NEAREST, GL_NEAREST);
    fbo_.attach_colour(0, colour_);
    fbo_.check_complete();
    std::vector<float> far(size_t(width) * size_t(height), 1.0f);
    set_depth(far);
}

void EnergyProbe::set_depth(std::span<const float> depth) {
    if (depth.size() != size_t(width_) * size_t(height_))
        throw std::invalid_argument("EnergyProbe: depth has " + std::to_string(depth.size()) + " values for " +
                                    std::to_string(width_) + "x" + std::to_string(height_));
    depth_.upload(GL_DEPTH_COMPONENT, GL_FLOAT, depth);
}

void EnergyProbe::draw_energy(EnergyPass& pass, const Camera& camera, std::span<const sim::EnergySegment> segments) {
    fbo_.bind();
    glViewport(0, 0, width_, height_);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, zero);
    gl::PipelineScope state(gl::kFullScreen);
    pass.draw_field(camera, depth_, width_, height_, segments, true);
}

void EnergyProbe::draw_glow(EnergyPass& pass, const Camera& camera, std::span<const sim::EnergySegment> segments,
                            std::span<const glm::vec4> background) {
    if (background.size() != size_t(width_) * size_t(height_))
        throw std::invalid_argument("EnergyProbe: background has the wrong pixel count");
    colour_.upload(GL_RGBA, GL_FLOAT, background);
    fbo_.bind();
    glViewport(0, 0, width_, height_);
    gl::PipelineScope state({.blend = gl::kAdd});
    pass.draw_field(camera, depth_, width_, height_, segments, false);
}

std::vector<glm::vec4> EnergyProbe::read() const {
    std::vector<glm::vec4> pixels(size_t(width_) * size_t(height_));
    glGetTextureImage(colour_.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(glm::vec4)), pixels.data());
    return pixels;
}

}  // namespace effects
