#include "effects/dust/FibreVolume.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "sim/core/Rng.h"

namespace effects {

namespace {

constexpr float kPi = 3.14159265f;

glm::vec3 random_direction(sim::Rng& rng, float climb) {
    float azimuth = rng.range(0.0f, 2.0f * kPi);
    return glm::normalize(glm::vec3(std::cos(azimuth), std::sin(azimuth), rng.range(-climb, climb)));
}

}  // namespace

FibreVolume grow_fibres(const FibreDirections& directions, const FibreGrowth& g) {
    if (directions.empty()) throw std::invalid_argument("fibre growth: the direction table is empty");
    if (g.size < 8 || g.size > 1024 || g.layers < 1 || g.layers > 64 || g.fibres < 1 || g.fibres > 100000 ||
        g.steps < 1 || g.steps > 10000)
        throw std::invalid_argument("fibre growth: size 8..1024, layers 1..64, fibres 1..100000 and steps 1..10000");
    FibreVolume v;
    v.size = g.size;
    v.layers = g.layers;
    v.texels.assign(size_t(g.size) * size_t(g.size) * size_t(g.layers) * 2, 0);
    sim::Rng rng(g.seed, 0xd057f1b3u);

    std::array<glm::vec3, FibreDirections::kCount> unit;
    for (int k = 0; k < FibreDirections::kCount; ++k) unit[size_t(k)] = glm::normalize(glm::vec3(FibreDirections::offset(k)));
    std::array<float, FibreDirections::kCount> weight{};

    for (int f = 0; f < g.fibres; ++f) {
        // Ranks spread evenly over the fibres so that a coverage fraction keeps that
        // fraction of them.
        const uint8_t rank = uint8_t(1 + (f * 254) / std::max(g.fibres - 1, 1));
        // Braces: the draws happen in order (a call's arguments are unsequenced).
        glm::ivec3 p{int(rng.below(uint32_t(g.size))), int(rng.below(uint32_t(g.size))),
                     std::min(g.layers - 1, int(std::pow(rng.unit(), g.bottom_heavy) * float(g.layers)))};
        glm::vec3 heading = random_direction(rng, g.climb);
        auto recompute = [&] {
            float sum = 0.0f;
            for (int k = 0; k < FibreDirections::kCount; ++k) {
                float w = directions.probability[size_t(k)] *
                          std::max(0.0f, 1.0f + g.direction_bias * glm::dot(unit[size_t(k)], heading));
                weight[size_t(k)] = w;
                sum += w;
            }
            return sum;
        };
        float total = recompute();
        for (int s = 0; s < g.steps; ++s) {
            size_t i = v.index(p.x, p.y, p.z);
            v.texels[i] = 255;
            v.texels[i + 1] = v.texels[i + 1] == 0 ? rank : std::min(v.texels[i + 1], rank);
            if (rng.unit() < g.bend_probability) {  // bend: a new global direction
                heading = random_direction(rng, g.climb);
                total = recompute();
            }
            if (!(total > 0.0f)) {  // the table allows nothing this way: turn round
                heading = -heading;
                total = recompute();
                if (!(total > 0.0f)) break;
            }
            float pick = rng.unit() * total;
            int k = 0;
            for (; k < FibreDirections::kCount - 1; ++k) {
                pick -= weight[size_t(k)];
                if (pick < 0.0f) break;
            }
            glm::ivec3 d = FibreDirections::offset(k);
            p.x = (p.x + d.x + g.size) % g.size;
            p.y = (p.y + d.y + g.size) % g.size;
            p.z = std::clamp(p.z + d.z, 0, g.layers - 1);
        }
    }
    return v;
}

}  // namespace effects
