#include "effects/rain/WindshieldCells.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace effects {

namespace {

// Marks every cell the glass rectangle [lo, hi] (metres, may reach past the glass) overlaps.
void mark(const WindshieldCellGrid& g, glm::vec2 lo, glm::vec2 hi, std::vector<uint8_t>& shown) {
    const glm::vec2 cells(float(g.columns), float(g.rows));
    const glm::vec2 a = glm::clamp(lo / g.glass_size_m * cells, glm::vec2(0.0f), cells - 1.0f);
    const glm::vec2 b = glm::clamp(hi / g.glass_size_m * cells, glm::vec2(0.0f), cells - 1.0f);
    for (int j = int(a.y); j <= int(b.y); ++j)
        for (int i = int(a.x); i <= int(b.x); ++i) shown[size_t(j * g.columns + i)] = 1;
}

}  // namespace

void shown_cells(const WindshieldCellGrid& g, const RainView& view, const ShownCellInputs& in,
                 std::vector<uint8_t>& shown) {
    shown.assign(size_t(g.columns) * size_t(g.rows), 0);
    constexpr float kFar = std::numeric_limits<float>::max();

    // Drops: the surface is 0 outside the wet tiles, and a bilinear lookup reaches one
    // texel past them (two here, against rounding).
    if (in.tiles && in.map_width > 0 && in.map_height > 0) {
        const glm::vec2 texel_m = g.glass_size_m / glm::vec2(float(in.map_width), float(in.map_height));
        constexpr int kTile = DropTiles::kTexels;
        for (const glm::uvec2& run : in.tiles->wet) {
            const int tx = int(run.x) % in.tiles->cols, ty = int(run.x) / in.tiles->cols;
            const glm::vec2 lo(float(tx * kTile - 2), float(ty * kTile - 2));
            const glm::vec2 hi(float((tx + int(run.y)) * kTile + 2), float((ty + 1) * kTile + 2));
            mark(g, lo * texel_m, hi * texel_m, shown);
        }
    }

    // The film: a bilinear lookup reaches one film cell past a wet one (clamped at the
    // edges, so an edge cell reaches out to the glass's edge). Half the shader's
    // threshold, against the filtering's rounding.
    if (in.film_strength > 0.0f && !view.film.empty() && view.film_cell_m > 0.0f) {
        const float visible = 0.5f * kFilmVisible * 255.0f / in.film_strength;
        for (int j = 0; j < view.film_rows; ++j)
            for (int i = 0; i < view.film_cols; ++i) {
                if (float(view.film[size_t(j * view.film_cols + i)]) <= visible) continue;
                const glm::vec2 lo(i == 0 ? -kFar : float(i - 1) * view.film_cell_m,
                                   j == 0 ? -kFar : float(j - 1) * view.film_cell_m);
                const glm::vec2 hi(i == view.film_cols - 1 ? kFar : float(i + 2) * view.film_cell_m,
                                   j == view.film_rows - 1 ? kFar : float(j + 2) * view.film_cell_m);
                mark(g, lo, hi, shown);
            }
    }

    // The blades and their arms, from the pivot to the blade's outer end: squares around
    // points along it no farther apart than the reach hold every point within reach.
    const float reach = in.blade_reach_m;
    if (reach > 0.0f)
        for (const WiperBladeView& b : view.blades) {
            const int steps = int(std::ceil(b.outer_m / reach));
            for (int s = 0; s <= steps; ++s) {
                const glm::vec2 p = b.pivot_m + b.direction * (b.outer_m * float(s) / float(std::max(steps, 1)));
                mark(g, p - 1.5f * reach, p + 1.5f * reach, shown);
            }
        }
}

}  // namespace effects
