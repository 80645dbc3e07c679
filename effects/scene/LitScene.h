#pragma once
// The lit opaque scene as the opaque pass and the rear-view mirror draw it: the
// objects' and the ground's programs (mesh.*.glsl over lighting.glsl) set up for a
// camera, and the sky behind what they drew.
#include <array>
#include <optional>
#include <string>

#include "effects/Quality.h"
#include "effects/gl/Program.h"
#include "effects/scene/Camera.h"
#include "effects/scene/FrameContext.h"
#include "effects/scene/LitProgram.h"

namespace effects {

class LitScene {
public:
    explicit LitScene(std::string label);  // the programs' labels start with it

    struct Programs {
        const gl::Program& objects;
        const gl::Program& ground;
        const gl::Program& open_sky_ground;  // the ground without the sky-occlusion lookup (OPEN_SKY)
    };
    // Both programs in the variant for `quality`, the line lights and the normals output,
    // with the frame's lighting, the ground's roads and wetness, and `camera`'s view set.
    Programs programs(const FrameContext& frame, const QualitySettings& quality, bool line_lights, bool normals,
                      const Camera& camera);

    // Depth only, with the lit programs' vertex stage (invariant gl_Position: the same
    // depth to the bit), for `camera`'s view.
    const gl::Program& depth(const Camera& camera);

    // The sky, only where nothing was drawn (the far plane passes GL_LEQUAL); applies
    // that depth state itself.
    void draw_sky(const FrameData& data, const Camera& camera, bool normals);

private:
    std::string label_;
    LitProgram objects_;
    std::optional<LitProgram> ground_, open_sky_ground_;  // made at the first frame: they need the level's road count
    std::optional<gl::Program> depth_;  // made at first use: the mirror never asks
    std::array<std::optional<gl::Program>, 2> sky_;  // without, with the normals output
};

}  // namespace effects
