#pragma once
// What happened during a tick that the sim itself never reads again: contacts, gates,
// laps, targets, shots, splashes, drops landing on the glass. The sound (audio/) and
// anything else outside the sim read it after the tick. It is cleared at the start of
// every step, written by the subsystems, never read by them and never hashed, so a
// world's hashes are the same whoever reads it (docs/AUDIO.md).
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/world/WorldEvents.h"

namespace sim {

enum class ContactBody : uint8_t { Car, Boat };

// A vehicle pushed out of a solid or back across an edge.
struct ContactReport {
    ContactBody body = ContactBody::Car;
    glm::vec3 position{0.0f};  // the touching point, on the ground plane at the body's height
    float impulse_ns = 0.0f;   // the normal impulse, N s
};

enum class ImpactSurface : uint8_t { Ground, Solid, Water };

struct ShotReport {
    glm::vec3 position{0.0f};  // the muzzle for a shot fired, the impact point for a hit
    ImpactSurface surface = ImpactSurface::Ground;
};

struct GateReport {
    uint32_t course = 0;
    uint32_t gate = 0;
    bool lap_finished = false;  // the start line closing a lap
};

struct TickReport {
    std::vector<ContactReport> contacts;
    std::vector<ShotReport> shots_fired;
    std::vector<ShotReport> shot_impacts;
    std::vector<WaterEntry> water_entries;  // this tick's splashes (objects and shots)
    std::vector<GateReport> gates;
    std::vector<glm::vec3> targets_hit;     // the targets' centres
    uint32_t glass_drops = 0;               // raindrops that reached the windshield
    float glass_drop_mg = 0.0f;             // their water

    void clear() {
        contacts.clear();
        shots_fired.clear();
        shot_impacts.clear();
        water_entries.clear();
        gates.clear();
        targets_hit.clear();
        glass_drops = 0;
        glass_drop_mg = 0.0f;
    }
};

}  // namespace sim
