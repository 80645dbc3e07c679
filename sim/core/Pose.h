#pragma once
// Rigid-body pose of a vehicle: model space has +x forward, +y up, +z to the right.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "sim/core/DetMath.h"

namespace sim {

struct Pose {
    glm::vec3 position{0.0f};
    float heading_rad = 0.0f;  // about +y; 0 faces +x
    float pitch_rad = 0.0f;    // nose up positive
    float roll_rad = 0.0f;     // leaning right positive

    template <class Archive> void describe(Archive& ar) {
        ar.vec(position);
        ar.f32(heading_rad);
        ar.f32(pitch_rad);
        ar.f32(roll_rad);
    }

    glm::vec3 forward_flat() const {
        float s, c;
        det::sincos(heading_rad, s, c);
        return {c, 0.0f, -s};
    }
    glm::vec3 right_flat() const {
        float s, c;
        det::sincos(heading_rad, s, c);
        return {s, 0.0f, c};
    }

    // Model-to-world: yaw, then pitch about the model's right axis, then roll.
    glm::mat4 matrix() const {
        float ch, sh, cp, sp, cr, sr;
        det::sincos(heading_rad, sh, ch);
        det::sincos(pitch_rad, sp, cp);
        det::sincos(roll_rad, sr, cr);
        glm::mat4 yaw(1.0f), pitch(1.0f), roll(1.0f);
        yaw[0] = {ch, 0, -sh, 0};
        yaw[2] = {sh, 0, ch, 0};
        pitch[0] = {cp, sp, 0, 0};
        pitch[1] = {-sp, cp, 0, 0};
        roll[1] = {0, cr, sr, 0};
        roll[2] = {0, -sr, cr, 0};
        glm::mat4 m = yaw * pitch * roll;
        m[3] = glm::vec4(position, 1.0f);
        return m;
    }
};

}  // namespace sim
