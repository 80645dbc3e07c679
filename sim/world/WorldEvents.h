#pragma once
// Things that happened during a tick that other subsystems react to later in the
// same tick (a splash needs to know an object entered the water). Cleared each tick.
#include <vector>

#include <glm/vec3.hpp>

namespace sim {

struct WaterEntry {
    glm::vec3 position{0.0f};  // where the body crossed the surface
    glm::vec3 velocity{0.0f};
    float radius_m = 0.0f;
    float mass_kg = 0.0f;
    bool sinks = false;  // denser than water
};

struct WorldEvents {
    std::vector<WaterEntry> water_entries;
    void clear() { water_entries.clear(); }
};

}  // namespace sim
