#include "effects/water/WaveGridMips.h"

#include <algorithm>

namespace effects {

void WaveGridMips::derive(const WaveHeights& grid) {
    const int n = grid.size;
    if (grid_size_ != n) {
        grid_size_ = n;
        level_offsets_.clear();
        size_t total = 0;
        for (int s = n;; s = std::max(s / 2, 1)) {
            level_offsets_.push_back(total);
            total += size_t(s) * size_t(s);
            if (s == 1) break;
        }
        texels_.assign(total, glm::vec4(0.0f));
    }
    const float* h = grid.heights.data();
    const float inv_spacing = 1.0f / grid.spacing_m;
    const float inv_spacing2 = inv_spacing * inv_spacing;
    glm::vec4* out = texels_.data();
    for (int j = 0; j < n; ++j) {
        const int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, n - 1);
        const float dz = 1.0f / float(std::max(j1 - j0, 1));
        const float* row = h + size_t(j) * n;
        const float* below = h + size_t(j0) * n;
        const float* above = h + size_t(j1) * n;
        for (int i = 0; i < n; ++i) {
            const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, n - 1);
            const float hx0 = row[i0], hx1 = row[i1], hz0 = below[i], hz1 = above[i], centre = row[i];
            const float dx = 1.0f / float(std::max(i1 - i0, 1));
            out[size_t(j) * n + i] = glm::vec4((hx1 - hx0) * dx * inv_spacing, (hz1 - hz0) * dz * inv_spacing,
                                               (hx0 + hx1 + hz0 + hz1 - 4.0f * centre) * inv_spacing2, centre);
        }
    }
    for (size_t k = 1; k < level_offsets_.size(); ++k) {
        const int src_n = level_size(int(k - 1)), dst_n = level_size(int(k));
        const glm::vec4* src = texels_.data() + level_offsets_[k - 1];
        glm::vec4* dst = texels_.data() + level_offsets_[k];
        for (int j = 0; j < dst_n; ++j) {
            const glm::vec4* r0 = src + size_t(std::min(2 * j, src_n - 1)) * src_n;
            const glm::vec4* r1 = src + size_t(std::min(2 * j + 1, src_n - 1)) * src_n;
            for (int i = 0; i < dst_n; ++i) {
                const int a = std::min(2 * i, src_n - 1), b = std::min(2 * i + 1, src_n - 1);
                dst[size_t(j) * dst_n + i] = 0.25f * ((r0[a] + r0[b]) + (r1[a] + r1[b]));
            }
        }
    }
}

std::span<const glm::vec4> WaveGridMips::level(int level) const {
    const size_t s = size_t(level_size(level));
    return {texels_.data() + level_offsets_[size_t(level)], s * s};
}

}  // namespace effects
