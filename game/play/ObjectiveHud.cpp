#include "game/play/ObjectiveHud.h"

#include <imgui.h>

#include "sim/objectives/Objectives.h"
#include "sim/player/Player.h"

namespace game {

std::vector<std::string> objective_hud_lines(const sim::World& world) {
    std::vector<std::string> lines;
    const auto* objectives = world.find<sim::Objectives>();
    if (!objectives) return lines;
    const auto* player = world.find<sim::Player>();
    const bool in_boat = player && player->vehicle() == sim::Vehicle::Boat;
    if (const sim::Course* course = objectives->course_for(in_boat ? sim::CourseVehicle::Boat : sim::CourseVehicle::Car)) {
        const size_t gates = course->desc().gates.size();
        if (course->lap_running())
            lines.push_back(course->desc().name + "  lap " + std::to_string(course->laps() + 1) + "  " +
                            lap_time_text(course->lap_ticks(world.tick())));
        else
            lines.push_back(course->desc().name + "  drive through the start gate");
        const size_t next = course->next_gate();
        lines.push_back("next gate " + (next == 0 ? std::string("finish") : std::to_string(next) + " of " + std::to_string(gates - 1)));
        lines.push_back("last " + (course->last_lap_ticks() ? lap_time_text(*course->last_lap_ticks()) : std::string("-")) +
                        "  best " + (course->best_lap_ticks() ? lap_time_text(*course->best_lap_ticks()) : std::string("-")));
    }
    if (!objectives->targets().states().empty()) lines.push_back(targets_line(objectives->targets()));
    return lines;
}

void draw_objective_hud(const sim::World& world) {
    const std::vector<std::string> lines = objective_hud_lines(world);
    if (lines.empty()) return;
    if (begin_top_hud_box("objectives", 10.0f)) {
        // The running lap stands out; the rest is plain.
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.85f, 0.3f, 1.0f));
        ImGui::TextUnformatted(lines[0].c_str());
        ImGui::PopStyleColor();
        for (size_t i = 1; i < lines.size(); ++i) ImGui::TextUnformatted(lines[i].c_str());
    }
    ImGui::End();
}

bool begin_top_hud_box(const char* name, float y) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + 0.5f * viewport->WorkSize.x, viewport->WorkPos.y + y),
                            ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.45f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoInputs;
    return ImGui::Begin(name, nullptr, flags);
}

}  // namespace game
