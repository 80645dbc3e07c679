#include "sim/world/World.h"

#include "sim/core/FloatEnvironment.h"
#include "sim/core/Hash.h"

namespace sim {

namespace {
// Bump when a change to the sim alters results for the same inputs.
constexpr uint64_t kSimVersion = 10;
}  // namespace

World::World(LevelDesc level, WorldOptions options) : World(std::move(level), standard_subsystems(), options) {}

World::World(LevelDesc level, const std::vector<SubsystemEntry>& list, WorldOptions options)
    : level_(std::move(level)),
      terrain_(level_),
      flat_sea_(level_.sea_level_m),
      sea_(&flat_sea_),
      jobs_(options.threads) {
    assemble(list);
}

void World::assemble(const std::vector<SubsystemEntry>& list) {
    std::vector<const SubsystemEntry*> made;
    for (const SubsystemEntry& entry : list) {
        if (named(entry.name)) throw std::invalid_argument("the subsystem list names '" + std::string(entry.name) + "' twice");
        std::unique_ptr<Subsystem> s = entry.make(level_);
        if (!s) continue;  // this level has none
        if (s->name() != entry.name)
            throw std::logic_error("the entry '" + std::string(entry.name) + "' made a subsystem called '" +
                                   std::string(s->name()) + "'");
        subsystems_.push_back(std::move(s));
        made.push_back(&entry);
    }
    for (const SubsystemEntry* entry : made)
        for (std::string_view read : entry->reads)
            if (!named(read))
                throw std::invalid_argument("subsystem '" + std::string(entry->name) + "' reads '" + std::string(read) +
                                            "', which this world does not have");
    for (size_t i = 0; i < subsystems_.size(); ++i) {
        subsystems_[i]->connect(SubsystemLinks(*made[i], subsystems_));
        if (const SeaSurface* sea = subsystems_[i]->sea_surface()) {
            if (sea_ != &flat_sea_) throw std::invalid_argument("two subsystems simulate the sea");
            sea_ = sea;
        }
    }
}

Subsystem* World::named(std::string_view name) const {
    for (const auto& s : subsystems_)
        if (s->name() == name) return s.get();
    return nullptr;
}

Subsystem* World::need(std::string_view name) const {
    if (Subsystem* s = named(name)) return s;
    throw std::logic_error("world has no subsystem '" + std::string(name) + "'");
}

const Subsystem* SubsystemLinks::find(std::string_view name, bool needed) const {
    const std::vector<std::string_view>& declared = needed ? asker_.reads : asker_.may_read;
    bool ok = false;
    for (std::string_view d : declared) ok = ok || d == name;
    if (!ok)
        throw std::logic_error("subsystem '" + std::string(asker_.name) + "' reads '" + std::string(name) +
                               "' without declaring it in its entry's " + (needed ? "reads" : "may_read") +
                               " (sim/world/SubsystemList.cpp)");
    for (const auto& s : subsystems_)
        if (s->name() == name) return s.get();
    return nullptr;  // never for one in `reads`: assembly checked
}

void World::step(TickInput input, StepObserver* observer) {
    require_float_environment();  // a few cycles a tick, against a silent desync
    input = quantise(input);
    events_.clear();
    report_.clear();
    StepContext ctx{input, previous_, *this, jobs_, kTickSeconds, tick_};
    for (size_t i = 0; i < subsystems_.size(); ++i) {
        if (observer) observer->before(i);
        subsystems_[i]->step(ctx);
        if (observer) observer->after(i);
    }
    report_.water_entries = events_.water_entries;
    previous_ = input;
    ++tick_;
}

WorldHash World::hash() const {
    WorldHash h;
    h.world = hash_combine(0x5350494e44524946ull, tick_);
    for (const auto& s : subsystems_) {
        uint64_t part = s->hash();
        h.parts.push_back(part);
        h.world = hash_combine(h.world, part);
    }
    return h;
}

std::vector<std::string> World::subsystem_names() const {
    std::vector<std::string> names;
    for (const auto& s : subsystems_) names.emplace_back(s->name());
    return names;
}

uint64_t World::sim_signature() const {
    Hasher h;
    h.u64(kSimVersion);
    for (const auto& s : subsystems_) {
        h.bytes(s->name().data(), s->name().size());
        h.u32(0);
    }
    return h.value();
}

}  // namespace sim
