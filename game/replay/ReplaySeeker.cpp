#include "game/replay/ReplaySeeker.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace game {

ReplaySeeker::ReplaySeeker(const std::vector<sim::TickInput>& inputs, sim::World& world, KeyframeStore& keyframes,
                           uint32_t near_interval)
    : inputs_(inputs), world_(world), keyframes_(keyframes), near_interval_(near_interval) {
    if (near_interval == 0 || keyframes.interval() % near_interval != 0)
        throw std::invalid_argument("seeker: the near interval must divide the keyframe interval");
    after_step();
}

void ReplaySeeker::after_step() {
    keyframes_.offer(world_);
    const uint64_t t = world_.tick();
    if (t % near_interval_ != 0 || t % keyframes_.interval() == 0 || near_.count(t)) return;
    // Only the keyframe interval the world is in: the one a step back needs.
    const uint64_t segment = t / keyframes_.interval();
    std::erase_if(near_, [&](const auto& e) { return e.first / keyframes_.interval() != segment; });
    near_.emplace(t, world_.snapshot(keyframes_.level_hash()));
}

void ReplaySeeker::advance() {
    world_.step(inputs_[size_t(world_.tick())]);
    after_step();
}

bool ReplaySeeker::step() {
    if (world_.tick() >= ticks()) return false;
    advance();
    return true;
}

uint64_t ReplaySeeker::seek(uint64_t tick) {
    tick = std::min(tick, ticks());
    // The latest start at or before the tick: the world itself, a near snapshot or a keyframe.
    const uint64_t now = world_.tick();
    std::optional<uint64_t> key = keyframes_.at_or_before(tick);
    std::optional<uint64_t> near;
    if (auto it = near_.upper_bound(tick); it != near_.begin()) near = std::prev(it)->first;
    const uint64_t best_snapshot = std::max(key.value_or(0), near.value_or(0));
    if (!(now <= tick && now >= best_snapshot)) {
        if (near && *near >= key.value_or(0)) world_.restore(near_.at(*near), keyframes_.level_hash());
        else if (key) keyframes_.restore(*key, world_);
        else throw std::logic_error("seeker: no snapshot at or before tick " + std::to_string(tick));
    }
    const uint64_t from = world_.tick();
    while (world_.tick() < tick) advance();
    return tick - from;
}

size_t ReplaySeeker::near_bytes() const {
    size_t n = 0;
    for (const auto& e : near_) n += e.second.size();
    return n;
}

}  // namespace game
