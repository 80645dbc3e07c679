#include "game/play/DebugUi.h"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "game/settings/Settings.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"

namespace game {

namespace {

std::string format(const char* fmt, auto... values) {
    char buf[160];
    std::snprintf(buf, sizeof buf, fmt, values...);
    return buf;
}

}  // namespace

const char* vehicle_name(sim::Vehicle v) { return v == sim::Vehicle::Car ? "car" : "boat"; }

// The settings file's names, so the HUD and the file agree.
const char* view_name(sim::ViewMode v) { return camera_setting_name(v); }

const char* wiper_name(sim::WiperMode m) { return wiper_setting_name(m); }

HudState hud_state(const sim::World& world) {
    const sim::Player& player = world.get<sim::Player>();
    HudState hud;
    hud.vehicle = player.vehicle();
    hud.view = player.view();
    hud.wipers = player.wipers();
    hud.rain_intensity = player.rain_intensity();
    hud.tick = world.tick();
    const float speed_mps = hud.vehicle == sim::Vehicle::Car ? world.get<sim::Car>().speed_mps()
                                                              : world.get<sim::Boat>().speed_mps();
    hud.speed_kmh = speed_mps * 3.6f;
    return hud;
}

std::vector<std::string> hud_lines(const HudState& hud) {
    std::vector<std::string> lines;
    std::string flags;
    if (hud.paused) flags += "PAUSED  ";
    if (hud.unfocused && !hud.paused) flags += "PAUSED (window not focused)  ";
    if (hud.behind) flags += "BEHIND REAL TIME  ";
    if (hud.recording) flags += "REC  ";
    if (!hud.status.empty()) flags += hud.status;
    if (!flags.empty()) lines.push_back(flags);
    lines.push_back(format("%.0f km/h  %s, %s view", double(hud.speed_kmh), vehicle_name(hud.vehicle),
                           view_name(hud.view)));
    lines.push_back(format("wipers %s  rain %.0f%%", wiper_name(hud.wipers), double(hud.rain_intensity) * 100.0));
    lines.push_back(format("tick %llu  %.1f fps", static_cast<unsigned long long>(hud.tick), hud.fps));
    if (!hud.quality.empty())
        lines.push_back(format("quality %s  scale %.2f (%dx%d)", hud.quality.c_str(), double(hud.render_scale),
                               hud.render_width, hud.render_height));
    return lines;
}

std::vector<ParamGroup> group_params(const std::vector<effects::Param>& params) {
    std::vector<ParamGroup> groups;
    for (size_t i = 0; i < params.size(); ++i) {
        ParamGroup* group = nullptr;
        for (ParamGroup& g : groups)
            if (g.name == params[i].group) group = &g;
        if (!group) group = &groups.emplace_back(ParamGroup{params[i].group, {}});
        group->params.push_back(i);
    }
    return groups;
}

DebugUi::DebugUi(GLFWwindow* window) : has_window_(window != nullptr) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini dropped into the working directory
    ImGui::StyleColorsDark();
    if (has_window_ && !ImGui_ImplGlfw_InitForOpenGL(window, true)) {
        ImGui::DestroyContext();
        throw std::runtime_error("Dear ImGui: the GLFW backend failed to initialise");
    }
    if (!ImGui_ImplOpenGL3_Init("#version 450")) {
        if (has_window_) ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        throw std::runtime_error("Dear ImGui: the OpenGL 3 backend failed to initialise for GLSL 4.50");
    }
}

DebugUi::~DebugUi() {
    ImGui_ImplOpenGL3_Shutdown();
    if (has_window_) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

bool DebugUi::wants_keyboard() const { return ImGui::GetIO().WantTextInput; }

void DebugUi::begin_frame(int width, int height) {
    ImGui_ImplOpenGL3_NewFrame();
    if (has_window_) {
        ImGui_ImplGlfw_NewFrame();
    } else {
        ImGuiIO& io = ImGui::GetIO();
        const auto now = std::chrono::steady_clock::now();
        io.DisplaySize = ImVec2(float(width), float(height));
        io.DeltaTime = std::max(1e-4f, std::chrono::duration<float>(now - last_frame_).count());
        last_frame_ = now;
    }
    ImGui::NewFrame();
}

void DebugUi::draw_hud(const HudState& hud) {
    ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.45f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoInputs;
    if (ImGui::Begin("hud", nullptr, flags)) {
        const std::vector<std::string> lines = hud_lines(hud);
        // The state line (PAUSED, BEHIND, REC, status) comes first when there is one and stands out.
        const bool has_state_line =
            hud.paused || hud.unfocused || hud.behind || hud.recording || !hud.status.empty();
        for (size_t i = 0; i < lines.size(); ++i) {
            const bool alert = has_state_line && i == 0;
            if (alert) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.3f, 1.0f));
            ImGui::TextUnformatted(lines[i].c_str());
            if (alert) ImGui::PopStyleColor();
        }
    }
    ImGui::End();
}

bool DebugUi::draw_debug_panel(effects::Renderer& renderer, QualityChoice& quality, bool* open) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 10.0f, viewport->WorkPos.y + 10.0f),
                            ImGuiCond_FirstUseEver, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(380.0f, viewport->WorkSize.y * 0.8f), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin(kDebugPanelTitle, open)) {
        ImGui::End();
        return false;
    }
    bool quality_changed = false;
    if (ImGui::BeginCombo("quality", std::string(quality_choice_name(quality)).c_str())) {
        for (QualityChoice c : kQualityChoices) {
            if (ImGui::Selectable(std::string(quality_choice_name(c)).c_str(), c == quality) && c != quality) {
                quality = c;
                quality_changed = true;
            }
        }
        ImGui::EndCombo();
    }
    ImGui::Text("render scale %.2f (%dx%d)", double(renderer.render_scale()), renderer.targets().width(),
                renderer.targets().height());
    bool profile = renderer.timing() == effects::gl::TimingMode::Profile;
    if (ImGui::Checkbox("profile timing (glFinish around every pass, F2)", &profile))
        renderer.set_timing(profile ? effects::gl::TimingMode::Profile : effects::gl::TimingMode::Sampled);
    if (!profile) ImGui::TextDisabled("one pass measured a frame, in turn");
    bool antialias = renderer.antialiasing();
    if (ImGui::Checkbox("anti-aliasing (FXAA, F3)", &antialias)) renderer.set_antialiasing(antialias);

    double total_ms = 0.0;
    if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableSetupColumn("pass");
        ImGui::TableSetupColumn("last ms");
        ImGui::TableSetupColumn("average ms");
        ImGui::TableHeadersRow();
        for (const effects::gl::PassTime& p : renderer.pass_times()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(p.name.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", p.ms);
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", p.average_ms);
            total_ms += p.average_ms;
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("total");
        ImGui::TableNextColumn();
        ImGui::TableNextColumn();
        ImGui::Text("%.2f", total_ms);
        ImGui::EndTable();
    }
    // What each pass sent through the rasteriser's vertex stage last frame.
    if (ImGui::BeginTable("draws", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableSetupColumn("pass");
        ImGui::TableSetupColumn("draws");
        ImGui::TableSetupColumn("triangles");
        ImGui::TableHeadersRow();
        effects::gl::DrawCount total;
        auto row = [](const char* name, const effects::gl::DrawCount& c) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(name);
            ImGui::TableNextColumn();
            ImGui::Text("%llu", static_cast<unsigned long long>(c.draws));
            ImGui::TableNextColumn();
            ImGui::Text("%llu", static_cast<unsigned long long>(c.triangles));
        };
        for (const effects::Renderer::PassDraws& d : renderer.pass_draws()) {
            row(d.name.c_str(), d.count);
            total.draws += d.count.draws;
            total.triangles += d.count.triangles;
        }
        row("frame", total);
        ImGui::EndTable();
    }

    const std::vector<effects::Param>& params = renderer.params().params();
    if (params.empty()) ImGui::TextDisabled("no params registered");
    for (const ParamGroup& group : group_params(params)) {
        if (!ImGui::CollapsingHeader(group.name.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) continue;
        for (size_t i : group.params) {
            const effects::Param& p = params[i];
            ImGui::PushID(int(i));  // names may repeat across groups
            switch (p.kind) {
                case effects::Param::Kind::Float:
                    ImGui::SliderFloat(p.name.c_str(), static_cast<float*>(p.value), p.min, p.max);
                    break;
                case effects::Param::Kind::Int:
                    ImGui::SliderInt(p.name.c_str(), static_cast<int*>(p.value), int(p.min), int(p.max));
                    break;
                case effects::Param::Kind::Bool:
                    ImGui::Checkbox(p.name.c_str(), static_cast<bool*>(p.value));
                    break;
            }
            ImGui::PopID();
        }
    }
    ImGui::End();
    return quality_changed;
}

void DebugUi::end_frame() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace game
