#pragma once
// A dust source's shadow map (seed §3, fig. 3): the depth of the nearest occluder
// seen from the source, rasterised on the CPU so the amounts are sim state. A point
// behind an occluder gets less dust from that source.
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace sim {

class SourceDepthMap {
public:
    // Looks from `source` at a sphere (centre, radius) that it frames exactly.
    SourceDepthMap(glm::vec3 source, glm::vec3 centre, float radius, int size);

    // Keeps the nearest depth per texel. Triangles reaching behind the near plane are
    // skipped (the source stands outside what it looks at).
    void rasterise(glm::vec3 a, glm::vec3 b, glm::vec3 c);
    // Fraction of the 3x3 texels around p's projection that see p (1 outside the map).
    float visibility(glm::vec3 p) const;

    int size() const { return size_; }
    const std::vector<float>& depths() const { return depth_; }  // view distance along the axis; +inf: empty

private:
    glm::mat4 view_proj_;
    float near_m_;
    int size_;
    std::vector<float> depth_;
};

}  // namespace sim
