#include "game/replay/ObjectiveSummary.h"

#include <cstdio>

#include "sim/objectives/Objectives.h"

namespace game {

namespace {
const char* vehicle_word(sim::CourseVehicle v) { return v == sim::CourseVehicle::Car ? "car" : "boat"; }
}  // namespace

std::string lap_time_text(uint64_t ticks) {
    const uint64_t hundredths = (ticks * 100 + sim::kTickRateHz / 2) / sim::kTickRateHz;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%llu:%02llu.%02llu", static_cast<unsigned long long>(hundredths / 6000),
                  static_cast<unsigned long long>(hundredths / 100 % 60), static_cast<unsigned long long>(hundredths % 100));
    return buf;
}

std::string targets_line(const sim::Targets& targets) {
    return "targets hit " + std::to_string(targets.hit_count()) + " of " + std::to_string(targets.states().size());
}

std::vector<std::string> objective_summary_lines(const sim::World& world) {
    std::vector<std::string> lines;
    const auto* objectives = world.find<sim::Objectives>();
    if (!objectives) return lines;
    for (const sim::Course& c : objectives->courses()) {
        std::string line = "course " + c.desc().name + " (" + vehicle_word(c.desc().vehicle) + "): " +
                           std::to_string(c.laps()) + (c.laps() == 1 ? " lap" : " laps");
        if (c.best_lap_ticks())
            line += ", last " + lap_time_text(*c.last_lap_ticks()) + ", best " + lap_time_text(*c.best_lap_ticks()) + " (" +
                    std::to_string(*c.best_lap_ticks()) + " ticks)";
        lines.push_back(line);
    }
    if (!objectives->targets().states().empty()) lines.push_back(targets_line(objectives->targets()));
    return lines;
}

}  // namespace game
