#include "sim/world/World.h"

#include "sim/core/FloatEnvironment.h"
#include "sim/core/Hash.h"

namespace sim {

namespace {
// Bump when a change to the sim alters results for the same inputs.
constexpr uint64_t kSimVersion = 10;
}  // namespace

World::World(LevelDesc level, WorldOptions options)
    : level_(std::move(level)),
      terrain_(level_),
      flat_sea_(level_.sea_level_m),
      sea_(&flat_sea_),
      jobs_(options.threads) {
    add_standard_subsystems(*this);
}

void World::add(std::unique_ptr<Subsystem> subsystem) { subsystems_.push_back(std::move(subsystem)); }

void World::step(TickInput input, StepObserver* observer) {
    require_float_environment();  // a few cycles a tick, against a silent desync
    input = quantise(input);
    events_.clear();
    StepContext ctx{input, previous_, *this, jobs_, kTickSeconds, tick_};
    for (size_t i = 0; i < subsystems_.size(); ++i) {
        if (observer) observer->before(i);
        subsystems_[i]->step(ctx);
        if (observer) observer->after(i);
    }
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

uint64_t World::build_hash() const {
    Hasher h;
    h.u64(kSimVersion);
    for (const auto& s : subsystems_) {
        h.bytes(s->name().data(), s->name().size());
        h.u32(0);
    }
    return h.value();
}

}  // namespace sim
