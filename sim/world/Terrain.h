#pragma once
// Ground heights, roads, decks and solids of a level, for everything that moves.
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/world/LevelDesc.h"

namespace sim {

class Terrain {
public:
    explicit Terrain(const LevelDesc& level);

    // Natural ground (land, hills, sea bed), ignoring decks.
    float ground_height(glm::vec2 xz) const;
    // Highest surface a wheel at height `from_y` can stand on: ground or a deck top no
    // more than `step_m` above from_y.
    float support_height(glm::vec2 xz, float from_y, float step_m = 0.6f) const;
    bool on_road(glm::vec2 xz) const;
    bool inside_world(glm::vec2 xz) const;
    // Push a vertical capsule-like cylinder (centre xz, radius, y range) out of the
    // solids. Returns the total push, or nullopt if nothing was touched.
    std::optional<glm::vec2> resolve_solids(glm::vec2& xz, float radius, float y_min, float y_max) const;
    // Where the straight path a -> b first enters a solid, as a fraction of the way
    // (0 if a is inside one), or nullopt if it meets none.
    std::optional<float> first_solid_hit(glm::vec3 a, glm::vec3 b) const;

    const LevelDesc& level() const { return level_; }

private:
    const LevelDesc& level_;
};

}  // namespace sim
