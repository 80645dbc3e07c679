#pragma once
// The deterministic world: a level, its subsystems in a fixed order, a tick counter.
// It is assembled from a list of subsystem entries (sim/world/SubsystemEntry.h), each
// connected once to what it reads. step() applies one quantised TickInput; hash()
// names every subsystem's state.
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/core/JobPool.h"
#include "sim/core/TickInput.h"
#include "sim/world/LevelDesc.h"
#include "sim/world/SeaSurface.h"
#include "sim/world/Subsystem.h"
#include "sim/world/SubsystemEntry.h"
#include "sim/world/Terrain.h"
#include "sim/world/TickReport.h"
#include "sim/world/WorldEvents.h"
#include "sim/world/WorldHash.h"

namespace sim {

inline constexpr int kTickRateHz = 60;
inline constexpr float kTickSeconds = 1.0f / kTickRateHz;

// Told before and after each subsystem steps: how the game times them without the
// sim reading a clock.
class StepObserver {
public:
    virtual ~StepObserver() = default;
    virtual void before(size_t subsystem_index) = 0;
    virtual void after(size_t subsystem_index) = 0;
};

struct WorldOptions {
    int threads = 1;  // results are the same for any count
};

class World {
public:
    // The game's world: every subsystem of the standard list the level has.
    explicit World(LevelDesc level, WorldOptions options = {});
    // A world of just the listed subsystems, stepped in the list's order. Throws
    // std::invalid_argument naming both when one reads a subsystem the world lacks.
    World(LevelDesc level, const std::vector<SubsystemEntry>& list, WorldOptions options = {});
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    void step(TickInput input, StepObserver* observer = nullptr);
    uint64_t tick() const { return tick_; }
    WorldHash hash() const;
    std::vector<std::string> subsystem_names() const;
    // The simulation signature: a hash of kSimVersion and the subsystem names (not of
    // the build), so it changes whenever either does: replays made by another sim are
    // refused rather than silently diverging.
    uint64_t sim_signature() const;

    // A snapshot of the whole state (sim/world/WorldSnapshot.cpp, docs/REPLAYS.md): a
    // fresh world of the same level restored from it steps on with exactly this one's
    // hashes. `level_hash` is the content hash of the level's files (the game loads them;
    // the sim never sees files), stored so that another level's snapshot is refused.
    std::vector<uint8_t> snapshot(uint64_t level_hash) const;
    // Throws SnapshotError (sim/core/StateArchive.h) with a message saying why for a
    // snapshot of another sim version or subsystems, or of another level (the world is
    // left as it was), or one that is cut or corrupt (the world is then half restored:
    // throw it away).
    void restore(std::span<const uint8_t> snapshot, uint64_t level_hash);
    // How many snapshots this world was restored from: a presentation cache that remembers
    // earlier frames (previous poses, uploaded revisions) resets when it changes.
    uint64_t restore_generation() const { return restore_generation_; }

    const LevelDesc& level() const { return level_; }
    const Terrain& terrain() const { return terrain_; }
    // A wave simulation in the world (Subsystem::sea_surface), else the flat sea.
    const SeaSurface& sea() const { return *sea_; }
    WorldEvents& events() { return events_; }
    const WorldEvents& events() const { return events_; }
    // What the last step did, for readers outside the sim (TickReport.h): subsystems
    // write it and never read it; it is not hashed.
    TickReport& report() { return report_; }
    const TickReport& report() const { return report_; }
    TickInput last_input() const { return previous_; }
    JobPool& jobs() { return jobs_; }

    const std::vector<std::unique_ptr<Subsystem>>& subsystems() const { return subsystems_; }

    // For the game, the renderer and tests; subsystems themselves read each other
    // through the links they are given at assembly.
    template <class T> const T* find() const { return static_cast<const T*>(named(T::kName)); }
    template <class T> T* find() { return static_cast<T*>(named(T::kName)); }
    template <class T> const T& get() const { return *static_cast<const T*>(need(T::kName)); }
    template <class T> T& get() { return *static_cast<T*>(need(T::kName)); }

private:
    void assemble(const std::vector<SubsystemEntry>& list);
    Subsystem* named(std::string_view name) const;
    Subsystem* need(std::string_view name) const;  // throws std::logic_error

    LevelDesc level_;
    Terrain terrain_;
    FlatSea flat_sea_;
    const SeaSurface* sea_;
    JobPool jobs_;
    WorldEvents events_;
    TickReport report_;
    std::vector<std::unique_ptr<Subsystem>> subsystems_;
    uint64_t tick_ = 0;
    TickInput previous_;
    uint64_t restore_generation_ = 0;
};

}  // namespace sim
