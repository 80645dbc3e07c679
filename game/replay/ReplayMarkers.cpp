#include "game/replay/ReplayMarkers.h"

#include <algorithm>

#include "game/replay/ObjectiveSummary.h"
#include "sim/objectives/Objectives.h"
#include "sim/player/Player.h"
#include "sim/water/WaterSim.h"

namespace game {

const char* marker_kind_name(MarkerKind kind) {
    switch (kind) {
        case MarkerKind::Gate: return "gate";
        case MarkerKind::Lap: return "lap";
        case MarkerKind::TargetHit: return "target hit";
        case MarkerKind::Shot: return "shot";
        case MarkerKind::Splash: return "splash";
        case MarkerKind::VehicleSwitch: return "vehicle switch";
    }
    return "?";
}

void ReplayMarkers::add(uint64_t tick, MarkerKind kind, std::string label) {
    if (!markers_.empty() && markers_.back().tick > tick) return;  // only forwards
    markers_.push_back({tick, kind, std::move(label)});
}

void ReplayMarkers::after_tick(const sim::World& world) {
    const uint64_t tick = world.tick();
    if (seen_ && tick != last_tick_ + 1) {  // not the next tick: compare from here on
        seen_ = false;
    }
    const sim::Player* player = world.find<sim::Player>();
    const sim::Objectives* objectives = world.find<sim::Objectives>();
    const int vehicle = player ? int(player->vehicle()) : 0;
    std::vector<uint64_t> gates, laps;
    size_t hits = 0;
    if (objectives) {
        for (const sim::Course& c : objectives->courses()) {
            gates.push_back(c.next_gate());
            laps.push_back(c.laps());
        }
        hits = objectives->targets().hit_count();
    }
    if (seen_) {
        if (vehicle != vehicle_) add(tick, MarkerKind::VehicleSwitch, vehicle == 0 ? "into the car" : "into the boat");
        for (size_t i = 0; objectives && i < gates.size(); ++i) {
            const sim::Course& c = objectives->courses()[i];
            if (laps[i] > laps_[i])
                add(tick, MarkerKind::Lap,
                    "lap " + std::to_string(laps[i]) + " of " + c.desc().name + ", " + lap_time_text(*c.last_lap_ticks()));
            else if (gates[i] != gates_[i])
                add(tick, MarkerKind::Gate, "gate " + std::to_string(gates_[i]) + " of " + c.desc().name);
        }
        if (hits > hits_) add(tick, MarkerKind::TargetHit, std::to_string(hits) + " target" + (hits > 1 ? "s" : "") + " hit");
        if (player && player->fires()) add(tick, MarkerKind::Shot, "shot");
        if (const sim::WaterSim* water = world.find<sim::WaterSim>())
            for (const sim::SplashEvent& e : water->splashes())
                if (e.kind == sim::SplashEvent::Kind::First) {
                    add(tick, MarkerKind::Splash, "splash");
                    break;
                }
    }
    seen_ = true;
    last_tick_ = tick;
    vehicle_ = vehicle;
    gates_ = std::move(gates);
    laps_ = std::move(laps);
    hits_ = hits;
}

std::optional<ReplayMarker> ReplayMarkers::next_after(uint64_t tick) const {
    auto it = std::upper_bound(markers_.begin(), markers_.end(), tick,
                               [](uint64_t t, const ReplayMarker& m) { return t < m.tick; });
    if (it == markers_.end()) return std::nullopt;
    return *it;
}

std::optional<ReplayMarker> ReplayMarkers::previous_before(uint64_t tick) const {
    auto it = std::lower_bound(markers_.begin(), markers_.end(), tick,
                               [](const ReplayMarker& m, uint64_t t) { return m.tick < t; });
    if (it == markers_.begin()) return std::nullopt;
    return *std::prev(it);
}

}  // namespace game
