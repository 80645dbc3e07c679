#pragma once
// How the objectives look (sim/objectives): each gate two posts and a banner across
// their tops, the next gate of each course glowing amber; crate targets standing on
// end until hit, then lying on their side; buoys that glow green once hit. Boxes and
// balls through the opaque scene's own programs, a handful of draws.
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/world/World.h"

namespace effects {

struct ObjectiveMarker {
    enum class Shape : uint8_t { Box, Ball };  // the unit cube [-1, 1]^3, the unit sphere
    enum class Glow : uint8_t { None, Next, Hit };
    Shape shape = Shape::Box;
    Glow glow = Glow::None;
    glm::mat4 transform{1.0f};
    glm::vec4 tint{1.0f};
    glm::vec3 lo{0.0f}, hi{0.0f};  // world bounds, for culling
};

// The markers of the world's objectives as of its last tick (none without them).
std::vector<ObjectiveMarker> objective_markers(const sim::World& world);

}  // namespace effects
