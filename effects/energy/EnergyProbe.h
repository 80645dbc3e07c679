#pragma once
// The energy pass on its own, over a depth buffer the caller gives: H per pixel in a
// float target (the exactness and NaN tests, the bench) or the glow over a background
// colour (the occlusion frame checks). Rows are in GL order (row 0 at the bottom).
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "effects/energy/EnergyPass.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Texture.h"

namespace effects {

class EnergyProbe {
public:
    EnergyProbe(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    // Window depths in [0, 1], width x height; without a call every ray runs to the far limit.
    void set_depth(std::span<const float> depth);
    // Raw H (red) and the ray's end distance (green) into the float target.
    void draw_energy(EnergyPass& pass, const Camera& camera, std::span<const sim::EnergySegment> segments);
    // The background colour, then the glow added over it.
    void draw_glow(EnergyPass& pass, const Camera& camera, std::span<const sim::EnergySegment> segments,
                   std::span<const glm::vec4> background);
    // The float target's pixels (waits for the GPU).
    std::vector<glm::vec4> read() const;

private:
    int width_, height_;
    gl::Texture depth_, colour_;
    gl::Framebuffer fbo_;
};

}  // namespace effects
