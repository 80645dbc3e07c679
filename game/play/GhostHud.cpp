#include "game/play/GhostHud.h"

#include <imgui.h>

#include <cstdio>
#include <cstdlib>

#include "game/play/ObjectiveHud.h"

namespace game {

namespace {

constexpr uint64_t kGapBrightTicks = 3 * sim::kTickRateHz;

}  // namespace

std::string gap_text(int64_t ticks) {
    const long long hundredths = (std::llabs(ticks) * 100 + sim::kTickRateHz / 2) / sim::kTickRateHz;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%s%lld.%02lld s", ticks > 0 ? "+" : ticks < 0 ? "-" : "", hundredths / 100,
                  hundredths % 100);
    return buf;
}

std::vector<std::string> ghost_hud_lines(const GhostRace& race) {
    std::vector<std::string> lines;
    lines.push_back("ghost " + race.name() +
                    (race.finished() ? " (ended at " + lap_time_text(race.replay().inputs.size()) + ")" : ""));
    if (race.gaps().empty()) return lines;
    const GateGap& g = race.gaps().back();
    const std::string where = g.gate == 0 ? (g.lap == 0 ? "start" : "finish of lap " + std::to_string(g.lap))
                                          : "gate " + std::to_string(g.gate) + ", lap " + std::to_string(g.lap);
    lines.push_back(g.course + " " + where + "  " + gap_text(g.gap_ticks));
    return lines;
}

void draw_ghost_hud(const GhostRace& race, uint64_t live_tick) {
    const std::vector<std::string> lines = ghost_hud_lines(race);
    // Under the objectives' box (four lines at the top of the middle).
    if (begin_top_hud_box("ghost", 20.0f + 5.0f * ImGui::GetTextLineHeightWithSpacing())) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.6f, 0.88f, 1.0f, 1.0f));  // the ghost's own pale blue
        ImGui::TextUnformatted(lines[0].c_str());
        ImGui::PopStyleColor();
        if (lines.size() > 1) {
            const bool fresh = live_tick < race.latest_gap_tick() + kGapBrightTicks;
            const int64_t gap = race.gaps().back().gap_ticks;
            const ImVec4 colour = gap > 0 ? ImVec4(1.0f, 0.35f, 0.3f, 1.0f) : ImVec4(0.35f, 1.0f, 0.45f, 1.0f);
            ImGui::PushStyleColor(ImGuiCol_Text, fresh ? colour : ImVec4(0.8f, 0.8f, 0.8f, 1.0f));
            ImGui::TextUnformatted(lines[1].c_str());
            ImGui::PopStyleColor();
        }
    }
    ImGui::End();
}

}  // namespace game
