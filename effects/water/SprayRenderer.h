#pragma once
// Spray droplets as camera-facing sprites: soft round discs, lit by the sky and the
// sun (brighter looking towards it), blended over the scene without writing depth;
// blurred near the eye and faded within a metre of it.
#include "effects/gl/Buffer.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/VertexArray.h"
#include "effects/scene/FrameContext.h"
#include "effects/water/WaterView.h"

namespace effects {

struct SprayLook {
    float min_pixels = 1.5f;  // smallest drawn diameter; smaller drops spread their light over it
    float blur_m = 0.02f;     // the eye's blur circle: drops near it are soft discs this wide
    float opacity = 0.7f;
};

class SprayRenderer {
public:
    SprayRenderer();

    // Uploads the drops and draws them into the scene colour, tested against the scene
    // depth, through a framebuffer of its own that has only those two attached: the
    // spray writes no normal, so the scene's normals are no draw buffer of it and stay
    // as they are. Sets and restores its own blend and depth-write state.
    void draw(const FrameContext& frame, std::span<const SprayDrop> drops, const SprayLook& look);

private:
    gl::Program program_;
    gl::Buffer instances_;
    gl::VertexArray vao_;
    gl::Framebuffer fbo_;  // scene colour and depth, re-made when the scene's targets are
    uint64_t generation_ = 0;  // SceneTargets::generation() fbo_ was built for
};

}  // namespace effects
