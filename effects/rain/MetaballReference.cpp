#include "effects/rain/MetaballReference.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "effects/rain/DropTiles.h"

namespace effects {

namespace {

constexpr float kReach2 = kMetaballReach * kMetaballReach;

float field(std::span<const RainMetaball> drops, std::span<const uint32_t> near, glm::vec2 p, float z2) {
    float sum = 0.0f;
    for (uint32_t k : near) {
        const RainMetaball& d = drops[k];
        const glm::vec2 e = p - d.centre_m;
        const float q = (e.x * e.x + e.y * e.y + z2) / (d.radius_m * d.radius_m);
        if (q < kReach2) sum += 1.0f / (1.0f + q * q);
    }
    return sum;
}

}  // namespace

float bisection_ceiling_m(std::span<const RainMetaball> drops) {
    float reach = 0.0f;
    for (const RainMetaball& d : drops) reach = std::max(reach, d.radius_m);
    return kMetaballReach * reach;
}

std::vector<SurfaceSample> reference_surface(std::span<const RainMetaball> drops, glm::vec2 glass_size_m, int width,
                                             int height, float threshold) {
    const float ceiling = bisection_ceiling_m(drops);
    const glm::vec2 texel = glass_size_m / glm::vec2(float(width), float(height));
    std::vector<float> h(size_t(width) * size_t(height), 0.0f);
    const DropTiles tiles = drops_by_tile(drops, glass_size_m, width, height);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const glm::uvec2 r = tiles.ranges[size_t(j / DropTiles::kTexels * tiles.cols + i / DropTiles::kTexels)];
            const std::span<const uint32_t> near(tiles.indices.data() + r.x, r.y);
            const glm::vec2 p = (glm::vec2(float(i), float(j)) + 0.5f) * texel;
            if (field(drops, near, p, 0.0f) <= threshold) continue;
            // The field falls with height above the glass: bisect for the iso-surface.
            float lo_z = 0.0f, hi_z = ceiling;
            for (int k = 0; k < kReferenceBisections; ++k) {
                const float mid = 0.5f * (lo_z + hi_z);
                (field(drops, near, p, mid * mid) > threshold ? lo_z : hi_z) = mid;
            }
            h[size_t(j) * size_t(width) + size_t(i)] = 0.5f * (lo_z + hi_z) * 1000.0f;
        }
    // Normals as the GPU path takes them: from the right and upper neighbours.
    std::vector<SurfaceSample> out(h.size());
    const glm::vec2 t_mm = texel * 1000.0f;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const size_t k = size_t(j) * size_t(width) + size_t(i);
            if (h[k] <= 0.0f) continue;
            const float hu = h[size_t(j) * size_t(width) + size_t(std::min(i + 1, width - 1))];
            const float hv = h[size_t(std::min(j + 1, height - 1)) * size_t(width) + size_t(i)];
            glm::vec3 n(-(hu - h[k]) * t_mm.y, -(hv - h[k]) * t_mm.x, t_mm.x * t_mm.y);
            out[k] = {n / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z), h[k]};
        }
    return out;
}

std::vector<RainMetaball> merged_drop_scene(glm::vec2& glass_size_m) {
    glass_size_m = {0.12f, 0.06f};
    std::vector<RainMetaball> d;
    auto add = [&](float u_mm, float v_mm, float r_mm) { d.push_back({{u_mm * 1e-3f, v_mm * 1e-3f}, r_mm * 1e-3f, 0.0f}); };
    // Two big drops merging, with a smaller one joining.
    add(25.0f, 30.0f, 6.0f);
    add(34.0f, 31.0f, 5.0f);
    add(30.0f, 22.0f, 3.5f);
    // A running drop and its trail of shrinking drops.
    add(62.0f, 16.0f, 4.5f);
    for (int k = 0; k < 7; ++k) add(61.0f + 0.6f * float(k % 2), 22.0f + 4.0f * float(k), 2.2f - 0.2f * float(k));
    // A bead of uniform particles packed along a wiper blade.
    for (int k = 0; k < 14; ++k) add(82.0f + 2.4f * float(k % 7), 24.0f + 2.6f * float(k / 7) + 1.2f * float(k % 2), 1.6f);
    // Scattered singles.
    add(100.0f, 45.0f, 3.0f);
    add(12.0f, 48.0f, 2.0f);
    add(108.0f, 12.0f, 4.0f);
    return d;
}

double mean_normal_angle_deg(std::span<const SurfaceSample> a, std::span<const SurfaceSample> b, size_t& wet_both) {
    double sum = 0.0;
    wet_both = 0;
    for (size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
        if (a[k].height_mm <= 0.0f || b[k].height_mm <= 0.0f) continue;
        const glm::vec3 x = a[k].normal, y = b[k].normal;
        const double c = std::clamp(double(x.x * y.x + x.y * y.y + x.z * y.z), -1.0, 1.0);
        sum += std::acos(c) * 180.0 / 3.14159265358979;
        ++wet_both;
    }
    return wet_both ? sum / double(wet_both) : 0.0;
}

}  // namespace effects
