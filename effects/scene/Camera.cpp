#include "effects/scene/Camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace effects {

Camera make_camera(const sim::CameraView& v, float aspect) {
    Camera c;
    c.eye = v.eye;
    c.view = glm::lookAt(v.eye, v.target, v.up);
    c.proj = glm::perspective(glm::radians(v.fov_y_deg), aspect, c.near_m, c.far_m);
    c.view_proj = c.proj * c.view;
    c.inv_view_proj = glm::inverse(c.view_proj);
    c.inv_proj = glm::inverse(c.proj);
    return c;
}

Camera jittered(Camera c, glm::vec2 ndc) {
    // In clip space x' = x + ndc.x * w: after the divide, every point moves by ndc.
    c.proj = glm::translate(glm::mat4(1.0f), glm::vec3(ndc, 0.0f)) * c.proj;
    c.view_proj = c.proj * c.view;
    c.inv_view_proj = glm::inverse(c.view_proj);
    c.inv_proj = glm::inverse(c.proj);
    c.jitter_ndc += ndc;
    return c;
}

}  // namespace effects
