#pragma once
// The moments of a replay worth jumping to (docs/REPLAYS.md, "The viewer"): gates, laps,
// target hits, shots, splashes and vehicle switches, found by watching the world after
// each tick (what changed since the tick before). The viewer marks them on its timeline
// and jumps to the next and previous one. No GL.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/world/World.h"

namespace game {

enum class MarkerKind : uint8_t { Gate, Lap, TargetHit, Shot, Splash, VehicleSwitch };
const char* marker_kind_name(MarkerKind kind);

struct ReplayMarker {
    uint64_t tick = 0;  // the world's tick count just after it happened
    MarkerKind kind = MarkerKind::Gate;
    std::string label;  // "lap 1 of quay, 0:21.80", "target 3 hit by a shot"
};

class ReplayMarkers {
public:
    // After each tick, in order from tick 1 (a world restored elsewhere starts afresh).
    void after_tick(const sim::World& world);

    const std::vector<ReplayMarker>& markers() const { return markers_; }
    // The first marker after `tick`, the last before it.
    std::optional<ReplayMarker> next_after(uint64_t tick) const;
    std::optional<ReplayMarker> previous_before(uint64_t tick) const;

private:
    void add(uint64_t tick, MarkerKind kind, std::string label);

    bool seen_ = false;
    uint64_t last_tick_ = 0;
    int vehicle_ = 0;
    std::vector<uint64_t> gates_, laps_;  // per course: next gate, laps
    size_t hits_ = 0;
    std::vector<ReplayMarker> markers_;  // ascending ticks
};

}  // namespace game
