#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/player/CameraRig.h"

namespace effects {

struct Camera {
    glm::mat4 view{1.0f}, proj{1.0f}, view_proj{1.0f}, inv_view_proj{1.0f}, inv_proj{1.0f};
    glm::vec3 eye{0.0f};
    float near_m = 0.1f, far_m = 4000.0f;
    // The projection's sub-pixel offset in normalised device coordinates (temporal
    // upsampling's jitter, TemporalPass); zero otherwise. view_proj and the inverses
    // include it.
    glm::vec2 jitter_ndc{0.0f};
};

Camera make_camera(const sim::CameraView& view, float aspect);
// `camera` with its projection moved by `ndc` (on top of any offset it had).
Camera jittered(Camera camera, glm::vec2 ndc);

}  // namespace effects
