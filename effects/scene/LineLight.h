#pragma once
// A light along a segment (an energy beam), as shaders/common/lighting.glsl's LineLights
// block holds it. The frame's line lights are frame data (FrameData::line_lights); no GL.
#include <cstddef>
#include <span>

#include <glm/vec3.hpp>

namespace effects {

inline constexpr size_t kMaxLineLights = 16;  // as lighting.glsl's kMaxLineLights

struct LineLight {
    glm::vec3 start{0.0f}, end{0.0f};
    float reach_m = 0.0f;
    float intensity = 0.0f;  // per metre of the segment
    glm::vec3 colour{1.0f};
};

// Whether `light` can reach into the box [lo, hi]: conservative (true may be out of
// reach, false never is), for drawing what no beam lights without the line-light sum.
bool line_light_reaches(const LineLight& light, glm::vec3 lo, glm::vec3 hi);
// Whether any of `lights` reaches into the box [lo, hi].
bool line_lights_reach(std::span<const LineLight> lights, glm::vec3 lo, glm::vec3 hi);

}  // namespace effects
