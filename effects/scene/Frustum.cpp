#include "effects/scene/Frustum.h"

namespace effects {

Frustum::Frustum(const glm::mat4& m) {
    glm::vec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]),
        r2(m[0][2], m[1][2], m[2][2], m[3][2]), r3(m[0][3], m[1][3], m[2][3], m[3][3]);
    planes_ = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
}

bool Frustum::outside(glm::vec3 lo, glm::vec3 hi) const {
    for (const glm::vec4& p : planes_) {
        glm::vec3 far_corner(p.x >= 0.0f ? hi.x : lo.x, p.y >= 0.0f ? hi.y : lo.y, p.z >= 0.0f ? hi.z : lo.z);
        if (p.x * far_corner.x + p.y * far_corner.y + p.z * far_corner.z + p.w < 0.0f) return true;
    }
    return false;
}

}  // namespace effects
