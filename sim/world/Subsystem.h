#pragma once
// One deterministic part of the world (car, boat, water, rain, ...). World steps its
// subsystems in a fixed order each tick and hashes each one; a snapshot saves and
// restores each one (sim/world/WorldSnapshot.h).
#include <cstdint>
#include <string_view>

#include "sim/core/JobPool.h"
#include "sim/core/TickInput.h"
#include "sim/world/SubsystemLinks.h"

namespace sim {

class World;
class SeaSurface;
class StateWriter;
class StateReader;

struct StepContext {
    TickInput input;     // held this tick
    TickInput previous;  // held last tick
    World& world;
    JobPool& jobs;
    float dt = 1.0f / 60.0f;
    uint64_t tick = 0;  // index of the tick being stepped (0-based)

    // True on the tick a control goes down: one-shot actions.
    bool pressed(Control c) const { return input.has(c) && !previous.has(c); }
};

class Subsystem {
public:
    virtual ~Subsystem() = default;
    virtual std::string_view name() const = 0;
    // Called once when the world is assembled: keep what the subsystem reads of the
    // others (only what its entry in the subsystem list declares).
    virtual void connect(const SubsystemLinks& links) { (void)links; }
    virtual void step(StepContext& ctx) = 0;
    // Hash, save and restore walk one description of the state (sim/core/StateArchive.h):
    // a subsystem derives from DescribedSubsystem, which makes all three from it.
    virtual uint64_t hash() const = 0;
    virtual void save(StateWriter& out) const = 0;
    // Throws SnapshotError when the bytes do not fit the description.
    virtual void restore(StateReader& in) = 0;
    // A subsystem that simulates the sea surface returns it: the world installs it
    // for boats and objects to ride.
    virtual const SeaSurface* sea_surface() const { return nullptr; }
};

}  // namespace sim
