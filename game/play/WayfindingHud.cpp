#include "game/play/WayfindingHud.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vector_relational.hpp>
#include <glm/vec4.hpp>

#include "effects/scene/Camera.h"
#include "game/play/DebugUi.h"

namespace game {

namespace {

float flat_distance(const glm::vec3& a, const glm::vec3& b) { return glm::length(glm::vec2(a.x - b.x, a.z - b.z)); }

}  // namespace

SwitchPrompt switch_prompt(sim::Vehicle aboard, const glm::vec3& car, const glm::vec3& boat) {
    // The same comparison as sim::Player::step, so the prompt never promises a switch
    // the sim refuses.
    const glm::vec2 d(car.x - boat.x, car.z - boat.z);
    const float reach = sim::Player::kSwitchDistance_m;
    if (d.x * d.x + d.y * d.y > reach * reach) return SwitchPrompt::None;
    return aboard == sim::Vehicle::Car ? SwitchPrompt::TakeBoat : SwitchPrompt::TakeCar;
}

std::string switch_prompt_text(SwitchPrompt prompt) {
    switch (prompt) {
        case SwitchPrompt::None: return "";
        case SwitchPrompt::TakeBoat: return "E: take the boat";
        case SwitchPrompt::TakeCar: return "E: take the car";
    }
    return "";
}

VehicleMarker vehicle_marker(sim::Vehicle aboard, const glm::vec3& car, const glm::vec3& boat,
                             const sim::CameraView& camera, float width, float height, float covered_bottom_px) {
    VehicleMarker m;
    m.vehicle = aboard == sim::Vehicle::Car ? sim::Vehicle::Boat : sim::Vehicle::Car;
    const glm::vec3 from = aboard == sim::Vehicle::Car ? car : boat;
    const glm::vec3 target = aboard == sim::Vehicle::Car ? boat : car;
    m.distance_m = flat_distance(from, target);
    m.shown = switch_prompt(aboard, car, boat) == SwitchPrompt::None && width > 0.0f && height > 0.0f;
    if (!m.shown) return m;

    const effects::Camera cam = effects::make_camera(camera, width / height);
    const glm::vec4 clip = cam.view_proj * glm::vec4(target + glm::vec3(0.0f, kMarkerHeight_m, 0.0f), 1.0f);
    const glm::vec2 centre(width * 0.5f, height * 0.5f);
    // The arrows' box: the screen less the margin, and less the covered band at its foot
    // (but never shrunk past the centre, from which the edge arrows are cast).
    const glm::vec2 lo(std::min(kMarkerEdgeMargin_px, centre.x - 1.0f), std::min(kMarkerEdgeMargin_px, centre.y - 1.0f));
    const glm::vec2 hi(width - lo.x, std::max(height - lo.y - std::max(covered_bottom_px, 0.0f), centre.y + 1.0f));
    if (clip.w > 1e-3f) {
        const glm::vec2 ndc(clip.x / clip.w, clip.y / clip.w);
        const glm::vec2 pixel = centre + glm::vec2(ndc.x, -ndc.y) * centre;
        if (glm::all(glm::greaterThanEqual(pixel, lo)) && glm::all(glm::lessThanEqual(pixel, hi))) {
            m.in_view = true;
            m.position = pixel;
            m.direction = {0.0f, 1.0f};  // pointing down at it
            return m;
        }
    }
    // Out of view: from the screen's centre towards it, out to the inset edge. The clip
    // position before the division by w keeps its side even behind the camera, where
    // the division would mirror it.
    glm::vec2 d = glm::vec2(clip.x, -clip.y) * centre;
    if (glm::length(d) < 1e-6f) d = {0.0f, 1.0f};  // straight behind: point down, towards the back
    const glm::vec2 room((d.x >= 0.0f ? hi.x : lo.x) - centre.x, (d.y >= 0.0f ? hi.y : lo.y) - centre.y);
    const float reach = std::min(std::fabs(room.x) / std::max(std::fabs(d.x), 1e-6f),
                                 std::fabs(room.y) / std::max(std::fabs(d.y), 1e-6f));
    m.direction = glm::normalize(d);
    m.position = centre + d * reach;
    return m;
}

void draw_wayfinding(SwitchPrompt prompt, const VehicleMarker& marker) {
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    ImFont* font = ImGui::GetFont();
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const ImU32 shadow = IM_COL32(0, 0, 0, 170);
    const ImU32 ink = IM_COL32(255, 226, 120, 255);

    const std::string text = switch_prompt_text(prompt);
    if (!text.empty()) {
        const float size = 2.0f * ImGui::GetFontSize();
        const ImVec2 extent = font->CalcTextSizeA(size, 1e9f, 0.0f, text.c_str());
        const ImVec2 at(viewport->Pos.x + (viewport->Size.x - extent.x) * 0.5f,
                        viewport->Pos.y + viewport->Size.y * 0.78f);
        const float pad = 0.4f * size;
        draw->AddRectFilled(ImVec2(at.x - pad, at.y - 0.5f * pad), ImVec2(at.x + extent.x + pad, at.y + extent.y + 0.5f * pad),
                            IM_COL32(0, 0, 0, 130), 0.5f * size);
        draw->AddText(font, size, at, ink, text.c_str());
    }

    if (!marker.shown) return;
    const glm::vec2 tip = marker.position + glm::vec2(viewport->Pos.x, viewport->Pos.y);
    const glm::vec2 dir = marker.direction, side(-dir.y, dir.x);
    // A notched arrowhead, long for its width, so that its point reads at a glance.
    constexpr float kLength = 30.0f, kHalfWidth = 13.0f, kNotch = 10.0f;
    const glm::vec2 base = tip - dir * kLength;
    const auto im = [](glm::vec2 v) { return ImVec2(v.x, v.y); };
    const ImVec2 head[4] = {im(tip), im(base + side * kHalfWidth), im(base + dir * kNotch),
                            im(base - side * kHalfWidth)};
    draw->AddTriangleFilled(head[0], head[1], head[2], ink);
    draw->AddTriangleFilled(head[0], head[2], head[3], ink);
    draw->AddPolyline(head, 4, shadow, ImDrawFlags_Closed, 2.0f);

    char label[48];
    std::snprintf(label, sizeof label, "%s %.0f m", vehicle_name(marker.vehicle), double(marker.distance_m));
    const float size = 1.4f * ImGui::GetFontSize();
    const ImVec2 extent = font->CalcTextSizeA(size, 1e9f, 0.0f, label);
    // The label sits behind the arrow's base, away from the edge it points at.
    const glm::vec2 label_centre = base - dir * (0.5f * std::fabs(dir.x) * extent.x + 0.5f * std::fabs(dir.y) * extent.y + 6.0f);
    const ImVec2 at(label_centre.x - 0.5f * extent.x, label_centre.y - 0.5f * extent.y);
    draw->AddText(font, size, ImVec2(at.x + 1.5f, at.y + 1.5f), shadow, label);
    draw->AddText(font, size, at, ink, label);
}

}  // namespace game
