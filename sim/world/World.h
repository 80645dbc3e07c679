#pragma once
// The deterministic world: a level, its subsystems in a fixed order, a tick counter.
// step() applies one quantised TickInput; hash() names every subsystem's state.
#include <memory>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <vector>

#include "sim/core/JobPool.h"
#include "sim/core/TickInput.h"
#include "sim/world/LevelDesc.h"
#include "sim/world/SeaSurface.h"
#include "sim/world/Subsystem.h"
#include "sim/world/Terrain.h"
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
    explicit World(LevelDesc level, WorldOptions options = {});
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    void step(TickInput input, StepObserver* observer = nullptr);
    uint64_t tick() const { return tick_; }
    WorldHash hash() const;
    std::vector<std::string> subsystem_names() const;
    // Changes whenever the subsystem list or the sim's version changes: replays made
    // by another sim are refused rather than silently diverging.
    uint64_t build_hash() const;

    const LevelDesc& level() const { return level_; }
    const Terrain& terrain() const { return terrain_; }
    const SeaSurface& sea() const { return *sea_; }
    // A wave simulation installs itself here; nullptr restores the flat sea.
    void set_sea(const SeaSurface* sea) { sea_ = sea ? sea : &flat_sea_; }
    WorldEvents& events() { return events_; }
    const WorldEvents& events() const { return events_; }
    TickInput last_input() const { return previous_; }
    JobPool& jobs() { return jobs_; }

    void add(std::unique_ptr<Subsystem> subsystem);
    const std::vector<std::unique_ptr<Subsystem>>& subsystems() const { return subsystems_; }

    template <class T> const T* find() const {
        for (const auto& s : subsystems_)
            if (auto* t = dynamic_cast<const T*>(s.get())) return t;
        return nullptr;
    }
    template <class T> T* find() {
        for (auto& s : subsystems_)
            if (auto* t = dynamic_cast<T*>(s.get())) return t;
        return nullptr;
    }
    template <class T> const T& get() const {
        if (const T* t = find<T>()) return *t;
        throw std::logic_error(std::string("world has no subsystem of type ") + typeid(T).name());
    }
    template <class T> T& get() {
        if (T* t = find<T>()) return *t;
        throw std::logic_error(std::string("world has no subsystem of type ") + typeid(T).name());
    }

private:
    LevelDesc level_;
    Terrain terrain_;
    FlatSea flat_sea_;
    const SeaSurface* sea_;
    JobPool jobs_;
    WorldEvents events_;
    std::vector<std::unique_ptr<Subsystem>> subsystems_;
    uint64_t tick_ = 0;
    TickInput previous_;
};

// Adds the game's subsystems in their stepping order (sim/world/SubsystemList.cpp):
// the one list an effect's sim part is added to.
void add_standard_subsystems(World& world);

}  // namespace sim
