#include "game/play/TimelineBar.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "game/play/ViewerKeys.h"
#include "sim/world/World.h"

namespace game {

namespace {

constexpr float kMargin = 12.0f;
constexpr float kBarHeight = 14.0f;

ImU32 marker_colour(MarkerKind kind) {
    switch (kind) {
        case MarkerKind::Gate: return IM_COL32(120, 200, 255, 255);
        case MarkerKind::Lap: return IM_COL32(255, 215, 80, 255);
        case MarkerKind::TargetHit: return IM_COL32(255, 90, 80, 255);
        case MarkerKind::Shot: return IM_COL32(255, 160, 60, 255);
        case MarkerKind::Splash: return IM_COL32(90, 230, 210, 255);
        case MarkerKind::VehicleSwitch: return IM_COL32(200, 130, 255, 255);
    }
    return IM_COL32_WHITE;
}

std::string speed_text(double speed) {
    char buf[16];
    std::snprintf(buf, sizeof buf, speed < 1.0 ? "%.2gx" : "%.0fx", speed);
    return buf;
}

}  // namespace

TimelineGeometry::TimelineGeometry(float left, float right, uint64_t ticks)
    : left_(left), right_(std::max(right, left)), ticks_(ticks) {}

float TimelineGeometry::x_of(uint64_t tick) const {
    if (ticks_ == 0) return left_;
    return left_ + (right_ - left_) * float(double(std::min(tick, ticks_)) / double(ticks_));
}

uint64_t TimelineGeometry::tick_at(float x) const {
    if (right_ <= left_) return 0;
    const double f = std::clamp(double(x - left_) / double(right_ - left_), 0.0, 1.0);
    return uint64_t(std::llround(f * double(ticks_)));
}

std::string replay_clock(uint64_t tick) {
    const double seconds = double(tick) / sim::kTickRateHz;
    const int minutes = int(seconds / 60.0);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%d:%05.2f", minutes, seconds - 60.0 * minutes);
    return buf;
}

TimelineDrawn draw_timeline(const TimelineState& s) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float width = viewport->WorkSize.x - 2.0f * kMargin;
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + kMargin, viewport->WorkPos.y + viewport->WorkSize.y - kMargin),
                            ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.55f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
    TimelineDrawn drawn;
    std::optional<uint64_t>& seek = drawn.seek;
    if (ImGui::Begin("timeline", nullptr, flags)) {
        const std::string now = replay_clock(s.tick), total = replay_clock(s.ticks);
        ImGui::Text("%s / %s   tick %llu / %llu   %s%s   camera: %s", now.c_str(), total.c_str(),
                    static_cast<unsigned long long>(s.tick), static_cast<unsigned long long>(s.ticks),
                    speed_text(s.speed).c_str(), s.paused ? "  PAUSED" : "", s.camera.c_str());
        if (!s.note.empty()) {
            ImGui::SameLine();
            ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.3f, 1.0f), "  %s", s.note.c_str());
        }

        // The bar: a button the width of the window, so a click on it is the timeline's.
        const ImVec2 top_left = ImGui::GetCursorScreenPos();
        const float bar_width = ImGui::GetContentRegionAvail().x;
        ImGui::InvisibleButton("bar", ImVec2(bar_width, kBarHeight + 8.0f));
        const TimelineGeometry geometry(top_left.x, top_left.x + bar_width, s.ticks);
        if (ImGui::IsItemActive()) seek = geometry.tick_at(ImGui::GetIO().MousePos.x);
        ImDrawList* draw = ImGui::GetWindowDrawList();
        const float y0 = top_left.y + 4.0f, y1 = y0 + kBarHeight;
        draw->AddRectFilled(ImVec2(top_left.x, y0), ImVec2(top_left.x + bar_width, y1), IM_COL32(60, 60, 70, 220), 3.0f);
        const float head = geometry.x_of(s.tick);
        draw->AddRectFilled(ImVec2(top_left.x, y0), ImVec2(head, y1), IM_COL32(70, 120, 190, 230), 3.0f);
        const ReplayMarker* hovered = nullptr;
        if (s.markers)
            for (const ReplayMarker& m : *s.markers) {
                const float x = std::round(geometry.x_of(m.tick));
                draw->AddLine(ImVec2(x, y0 - 3.0f), ImVec2(x, y1 + 3.0f), marker_colour(m.kind), 2.0f);
                if (ImGui::IsItemHovered() && std::abs(ImGui::GetIO().MousePos.x - x) <= 3.0f) hovered = &m;
            }
        draw->AddTriangleFilled(ImVec2(head - 6.0f, y0 - 5.0f), ImVec2(head + 6.0f, y0 - 5.0f), ImVec2(head, y0 + 3.0f),
                                IM_COL32_WHITE);
        draw->AddLine(ImVec2(head, y0), ImVec2(head, y1 + 3.0f), IM_COL32_WHITE, 2.0f);
        if (hovered)
            ImGui::SetTooltip("%s  %s", replay_clock(hovered->tick).c_str(), hovered->label.c_str());
        else if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s", replay_clock(geometry.tick_at(ImGui::GetIO().MousePos.x)).c_str());
        ImGui::TextDisabled("%s", viewer_keys_hint());
    }
    drawn.covered_px = ImGui::GetWindowHeight() + kMargin;
    ImGui::End();
    return drawn;
}

}  // namespace game
