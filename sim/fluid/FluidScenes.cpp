#include "sim/fluid/FluidScenes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/core/Rng.h"

namespace sim {

std::vector<glm::vec3> fill_block(glm::vec3 lo, glm::vec3 hi, float r, int count, uint64_t seed) {
    const float s = 2.0f * r;
    const int nx = int(std::floor((hi.x - lo.x - s) / s)) + 1;
    const int ny = int(std::floor((hi.y - lo.y - s) / s)) + 1;
    const int nz = int(std::floor((hi.z - lo.z - s) / s)) + 1;
    if (count < 0 || nx < 1 || ny < 1 || nz < 1 || int64_t(count) > int64_t(nx) * ny * nz)
        throw std::invalid_argument("fluid: particle_count " + std::to_string(count) + " does not fit the tank (at most " +
                                    std::to_string(std::max(nx, 0) * std::max(ny, 0) * std::max(nz, 0)) + ")");
    Rng rng(seed, 0x46494c4cull);  // "FILL"
    std::vector<glm::vec3> out;
    out.reserve(size_t(count));
    for (int j = 0; j < ny && int(out.size()) < count; ++j)
        for (int k = 0; k < nz && int(out.size()) < count; ++k)
            for (int i = 0; i < nx && int(out.size()) < count; ++i) {
                const glm::vec3 jitter = rng.range3(-0.1f, 0.1f);
                out.push_back(lo + glm::vec3(r) + (glm::vec3(float(i), float(j), float(k)) + jitter) * s);
            }
    return out;
}

FluidScene wave_scene(int count) {
    FluidScene s;
    s.params.particle_radius_m = 0.01f;
    s.params.box_size_m = {3.0f, 1.4f, 1.0f};
    s.params.ceiling_m = 1.6f;
    // A column one metre deep across the box, as tall as the count needs.
    const float area = 0.9f * 1.0f, per = 0.02f * 0.02f * 0.02f;
    const float height = std::min(1.35f, float(count) * per / area * 1.05f + 0.04f);
    s.particles = fill_block({0.0f, 0.0f, 0.0f}, {0.9f, height, 1.0f}, 0.01f, count, 5);
    return s;
}

FluidScene step_scene(int count) {
    FluidScene s;
    s.params.particle_radius_m = 0.01f;
    s.params.box_size_m = {3.0f, 1.2f, 0.8f};
    s.params.ceiling_m = 1.4f;
    s.boxes.push_back({{1.4f, 0.0f, 0.0f}, {3.0f, 0.25f, 0.8f}});
    const float area = 0.6f * 0.8f, per = 0.02f * 0.02f * 0.02f;
    const float height = std::min(1.15f, float(count) * per / area * 1.05f + 0.04f);
    s.particles = fill_block({0.0f, 0.0f, 0.0f}, {0.6f, height, 0.8f}, 0.01f, count, 6);
    return s;
}

}  // namespace sim
