#include "effects/water/WaterView.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace effects {

namespace {
// Larger grids are refused rather than uploaded (the sim allows up to 2048).
constexpr int kMaxGridSide = 2048;
constexpr int kMaxSheetSide = 1024;
}  // namespace

void WaterView::validate() const {
    if (!std::isfinite(sea_level_m)) throw std::invalid_argument("water view: sea level is not finite");
    if (grid) {
        const WaveHeights& g = *grid;
        if (g.size < 2 || g.size > kMaxGridSide)
            throw std::invalid_argument("water view: wave grid size " + std::to_string(g.size) + " outside 2.." +
                                        std::to_string(kMaxGridSide));
        if (!(g.spacing_m > 0.0f) || !std::isfinite(g.spacing_m))
            throw std::invalid_argument("water view: wave grid spacing must be positive and finite");
        if (!std::isfinite(g.origin_xz.x) || !std::isfinite(g.origin_xz.y))
            throw std::invalid_argument("water view: wave grid origin is not finite");
        if (g.heights.size() != size_t(g.size) * size_t(g.size))
            throw std::invalid_argument("water view: wave grid of size " + std::to_string(g.size) + " has " +
                                        std::to_string(g.heights.size()) + " heights, needs size*size");
    }
    for (size_t k = 0; k < sheets.size(); ++k) {
        const SheetView& s = sheets[k];
        const std::string which = "water view: splash sheet " + std::to_string(k);
        if (s.size < 2 || s.size > kMaxSheetSide)
            throw std::invalid_argument(which + " has size " + std::to_string(s.size) + ", outside 2.." +
                                        std::to_string(kMaxSheetSide));
        if (!(s.spacing_m > 0.0f) || !std::isfinite(s.spacing_m))
            throw std::invalid_argument(which + " has a spacing that is not positive and finite");
        if (s.centre_xz && !(std::isfinite(s.centre_xz->x) && std::isfinite(s.centre_xz->y)))
            throw std::invalid_argument(which + " has a centre that is not finite");
        const size_t n = size_t(s.size) * size_t(s.size);
        if (s.positions.size() != n || s.airborne.size() != n)
            throw std::invalid_argument(which + " has " + std::to_string(s.positions.size()) + " positions and " +
                                        std::to_string(s.airborne.size()) + " airborne flags, needs size*size = " +
                                        std::to_string(n));
        if (!s.velocities.empty() && s.velocities.size() != n)
            throw std::invalid_argument(which + " has " + std::to_string(s.velocities.size()) +
                                        " velocities, needs none or size*size = " + std::to_string(n));
        if (!(s.gravity_mps2 > 0.0f) || !std::isfinite(s.gravity_mps2))
            throw std::invalid_argument(which + " has a gravity that is not positive and finite");
    }
    if (!(tick_s > 0.0f) || !std::isfinite(tick_s))
        throw std::invalid_argument("water view: tick length must be positive and finite");
}

}  // namespace effects
