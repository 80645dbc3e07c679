#include "effects/scene/LineLight.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace effects {

bool line_light_reaches(const LineLight& l, glm::vec3 lo, glm::vec3 hi) {
    // A point within reach of the segment lies in the box grown by the reach on every
    // side, so a segment that misses the grown box (slab test) reaches none of it.
    const glm::vec3 glo = lo - l.reach_m, ghi = hi + l.reach_m, d = l.end - l.start;
    float t0 = 0.0f, t1 = 1.0f;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-9f) {
            if (l.start[a] < glo[a] || l.start[a] > ghi[a]) return false;
            continue;
        }
        float ta = (glo[a] - l.start[a]) / d[a], tb = (ghi[a] - l.start[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

bool line_lights_reach(std::span<const LineLight> lights, glm::vec3 lo, glm::vec3 hi) {
    return std::any_of(lights.begin(), lights.end(), [&](const LineLight& l) { return line_light_reaches(l, lo, hi); });
}

}  // namespace effects
