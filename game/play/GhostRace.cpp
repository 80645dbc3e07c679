#include "game/play/GhostRace.h"

#include "sim/objectives/Objectives.h"
#include "sim/player/Player.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"

namespace game {

void GatePasses::after_tick(const sim::World& world) {
    const auto* objectives = world.find<sim::Objectives>();
    if (!objectives) return;
    const std::vector<sim::Course>& courses = objectives->courses();
    if (ticks_.empty()) {
        ticks_.resize(courses.size());
        next_gate_.assign(courses.size(), 0);
    }
    // A course takes at most one gate a tick (the next one), so a changed next gate is
    // one pass.
    for (size_t c = 0; c < courses.size(); ++c)
        if (courses[c].next_gate() != next_gate_[c]) {
            next_gate_[c] = courses[c].next_gate();
            ticks_[c].push_back(world.tick());
        }
}

namespace {

effects::FramePoses::Ghost vehicle_pose(const sim::World& world) {
    const sim::Vehicle vehicle = world.get<sim::Player>().vehicle();
    return {vehicle, vehicle == sim::Vehicle::Car ? world.get<sim::Car>().pose() : world.get<sim::Boat>().pose()};
}

sim::LevelDesc with_seed(sim::LevelDesc level, uint64_t seed) {
    level.seed = seed;
    return level;
}

}  // namespace

GhostRace::GhostRace(Replay replay, std::string name, const sim::LevelDesc& level, int threads)
    : replay_(std::move(replay)),
      name_(std::move(name)),
      level_(with_seed(level, replay_.header.seed)),
      threads_(threads) {
    restart();
}

void GhostRace::restart() {
    world_ = std::make_unique<sim::World>(level_, sim::WorldOptions{threads_});
    previous_ = pose();
    live_ = {};
    ghost_ = {};
    compared_.clear();
    gaps_.clear();
    latest_gap_tick_ = 0;
}

effects::FramePoses::Ghost GhostRace::pose() const { return vehicle_pose(*world_); }

effects::FramePoses::Ghost GhostRace::pose_between(float alpha) const {
    effects::FramePoses from, to;
    from.ghost = previous_;
    to.ghost = pose();
    return *effects::interpolate(from, to, alpha).ghost;
}

void GhostRace::after_live_tick(const sim::World& live) {
    previous_ = pose();
    // Lockstep: the ghost's world is at the live world's tick count after this.
    while (world_->tick() < live.tick() && !finished()) {
        world_->step(sim::quantise(replay_.inputs[world_->tick()]));
        ghost_.after_tick(*world_);
    }
    live_.after_tick(live);
    compare(live.tick());
}

void GhostRace::compare(uint64_t now) {
    const auto* objectives = world_->find<sim::Objectives>();
    if (!objectives) return;
    const auto& live = live_.ticks();
    const auto& ghost = ghost_.ticks();
    compared_.resize(objectives->courses().size(), 0);
    for (size_t c = 0; c < compared_.size() && c < live.size() && c < ghost.size(); ++c) {
        const size_t gates = objectives->courses()[c].desc().gates.size();
        for (size_t& n = compared_[c]; n < live[c].size() && n < ghost[c].size(); ++n) {
            const size_t gate = n % gates;
            const uint32_t lap = uint32_t(gate == 0 ? n / gates : n / gates + 1);
            gaps_.push_back({objectives->courses()[c].desc().name, gate, lap,
                             int64_t(live[c][n]) - int64_t(ghost[c][n])});
            latest_gap_tick_ = now;
        }
    }
}

}  // namespace game
