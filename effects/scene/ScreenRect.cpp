#include "effects/scene/ScreenRect.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace effects {

glm::ivec4 screen_rect_of_box(const glm::mat4& view_proj, float near_w, glm::vec3 lo, glm::vec3 hi, int width,
                              int height, int margin) {
    glm::vec4 clip[8];
    for (int k = 0; k < 8; ++k)
        clip[k] = view_proj * glm::vec4((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z, 1.0f);
    glm::vec2 pmin(1e30f), pmax(-1e30f);
    bool any = false;
    auto add = [&](const glm::vec4& c) {
        const glm::vec2 ndc = glm::vec2(c) / c.w;
        pmin = glm::min(pmin, ndc);
        pmax = glm::max(pmax, ndc);
        any = true;
    };
    // The corners in front of the near plane, and where the box's edges cross it.
    for (int k = 0; k < 8; ++k) {
        if (clip[k].w >= near_w) add(clip[k]);
        for (int axis = 1; axis < 8; axis <<= 1) {
            const int j = k | axis;
            if (j == k) continue;
            const float a = clip[k].w - near_w, b = clip[j].w - near_w;
            if ((a < 0.0f) != (b < 0.0f)) add(glm::mix(clip[k], clip[j], a / (a - b)));
        }
    }
    if (!any) return glm::ivec4(0);
    const glm::vec2 size{float(width), float(height)};
    pmin = (glm::clamp(pmin, -2.0f, 2.0f) * 0.5f + 0.5f) * size;  // beyond the screen's edges counts as at them
    pmax = (glm::clamp(pmax, -2.0f, 2.0f) * 0.5f + 0.5f) * size;
    glm::ivec4 r(int(std::floor(pmin.x)) - margin, int(std::floor(pmin.y)) - margin, int(std::ceil(pmax.x)) + margin,
                 int(std::ceil(pmax.y)) + margin);
    r = glm::clamp(r, glm::ivec4(0), glm::ivec4(width, height, width, height));
    if (r.z <= r.x || r.w <= r.y) return glm::ivec4(0);
    return r;
}

}  // namespace effects
