#pragma once
// The six clip planes of a view-projection matrix, to skip what a view cannot see
// before the GPU (here a CPU rasteriser, for which every triangle set up costs) does.
#include <array>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace effects {

class Frustum {
public:
    // Gribb & Hartmann: the planes of clip space, normals inward.
    explicit Frustum(const glm::mat4& view_proj);

    // True when the axis-aligned box [lo, hi] lies wholly outside one plane (so cannot
    // be seen; a box outside no single plane may still be outside, which only costs a draw).
    bool outside(glm::vec3 lo, glm::vec3 hi) const;

private:
    std::array<glm::vec4, 6> planes_;
};

}  // namespace effects
