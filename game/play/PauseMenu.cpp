#include "game/play/PauseMenu.h"

#include <imgui.h>

#include <algorithm>

#include "game/play/GamepadInput.h"
#include "game/settings/KeyNames.h"

namespace game {

namespace {

// Dear ImGui's font is 13 px: at 720 lines it wants a third more, and it grows with
// the window so the menu reads the same at any size.
float text_scale(float height) { return std::clamp(height / 540.0f, 1.0f, 4.0f); }

// Dear ImGui's font at `scale` from here to its destructor, title bars included.
class ScaledFont {
public:
    explicit ScaledFont(float scale) : font_(ImGui::GetFont()), old_(font_->Scale) {
        font_->Scale = scale;
        ImGui::PushFont(font_);
    }
    ~ScaledFont() {
        ImGui::PopFont();
        font_->Scale = old_;
    }
    ScaledFont(const ScaledFont&) = delete;
    ScaledFont& operator=(const ScaledFont&) = delete;

private:
    ImFont* font_;
    float old_;
};

const char* button_name(int button) {
    switch (button) {
        case GLFW_GAMEPAD_BUTTON_A: return "A";
        case GLFW_GAMEPAD_BUTTON_B: return "B";
        case GLFW_GAMEPAD_BUTTON_X: return "X";
        case GLFW_GAMEPAD_BUTTON_Y: return "Y";
        case GLFW_GAMEPAD_BUTTON_LEFT_BUMPER: return "LB";
        case GLFW_GAMEPAD_BUTTON_RIGHT_BUMPER: return "RB";
        case GLFW_GAMEPAD_BUTTON_BACK: return "Back";
        case GLFW_GAMEPAD_BUTTON_START: return "Start";
        case GLFW_GAMEPAD_BUTTON_DPAD_UP: return "D-pad up";
        case GLFW_GAMEPAD_BUTTON_DPAD_DOWN: return "D-pad down";
        case GLFW_GAMEPAD_BUTTON_DPAD_LEFT: return "D-pad left";
        case GLFW_GAMEPAD_BUTTON_DPAD_RIGHT: return "D-pad right";
        default: return "?";
    }
}

// A combo over `options`, named by `name_of`; true when the choice changed.
template <typename T, size_t N>
bool choice_combo(const char* label, T& value, const T (&options)[N], auto name_of) {
    bool changed = false;
    if (ImGui::BeginCombo(label, std::string(name_of(value)).c_str())) {
        for (T o : options)
            if (ImGui::Selectable(std::string(name_of(o)).c_str(), o == value) && o != value) {
                value = o;
                changed = true;
            }
        ImGui::EndCombo();
    }
    return changed;
}

bool percent_slider(const char* label, float& value) {
    float percent = value * 100.0f;
    if (!ImGui::SliderFloat(label, &percent, 0.0f, 100.0f, "%.0f %%")) return false;
    value = std::clamp(percent / 100.0f, 0.0f, 1.0f);
    return true;
}

constexpr sim::ViewMode kViews[] = {sim::ViewMode::Chase, sim::ViewMode::Driver};
constexpr sim::WiperMode kWipers[] = {sim::WiperMode::Off, sim::WiperMode::Intermittent, sim::WiperMode::Low,
                                      sim::WiperMode::High};

}  // namespace

std::string gamepad_name(Action action) {
    const ActionInfo& info = action_info(action);
    switch (action) {
        case Action::Throttle: return "right trigger";
        case Action::Brake: return "left trigger";
        case Action::SteerLeft:
        case Action::SteerRight: return "left stick";
        default: break;
    }
    for (const GamepadBinding& b : gamepad_bindings())
        if ((info.control && b.control == info.control) || (info.ui && b.action == info.ui)) return button_name(b.button);
    return "";
}

void draw_menu_hint(float seconds_left) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float opacity = std::clamp(seconds_left, 0.0f, 1.0f);
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x * 0.5f,
                                   viewport->WorkPos.y + viewport->WorkSize.y - 24.0f),
                            ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.55f * opacity);
    ImGui::PushStyleVar(ImGuiStyleVar_Alpha, opacity);
    const ScaledFont scaled(text_scale(viewport->WorkSize.y));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
    if (ImGui::Begin("menu hint", nullptr, flags)) ImGui::TextUnformatted("Esc: menu and controls");
    ImGui::End();
    ImGui::PopStyleVar();
}

void PauseMenu::open() {
    open_ = true;
    page_ = Page::Main;
    focus_first_ = true;
    capture_.reset();
    message_.clear();
}

void PauseMenu::close() {
    open_ = false;
    capture_.reset();
}

void PauseMenu::tap(int glfw_key) {
    ImGuiIO& io = ImGui::GetIO();
    if (!open_ || glfw_key < 0 || glfw_key >= int(IM_ARRAYSIZE(io.KeysDown))) return;
    io.KeysDown[glfw_key] = true;
    tapped_.push_back(glfw_key);
    // Enter is text input to 1.86's navigation and Space activates: players press Enter.
    if ((glfw_key == GLFW_KEY_ENTER || glfw_key == GLFW_KEY_KP_ENTER) && !capture_) {
        io.KeysDown[GLFW_KEY_SPACE] = true;
        tapped_.push_back(GLFW_KEY_SPACE);
    }
}

void PauseMenu::key_pressed(int glfw_key, Settings& settings) {
    if (!capture_) return;
    if (glfw_key == kMenuKey)
        message_ = "not changed";
    else
        message_ = settings.keys.bind(capture_->action, capture_->slot, glfw_key).message;
    capture_.reset();
}

PauseMenu::Choice PauseMenu::draw(Settings& settings, const Context& context) {
    ImGuiIO& io = ImGui::GetIO();
    // Keyboard and gamepad steer the menu only while it is open (arrows drive the car
    // otherwise), and not while a key is being captured (Enter would press the button again).
    if (open_ && !capture_)
        io.ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard | ImGuiConfigFlags_NavEnableGamepad;
    else
        io.ConfigFlags &= ~(ImGuiConfigFlags_NavEnableKeyboard | ImGuiConfigFlags_NavEnableGamepad);
    if (!open_) {
        tapped_.clear();
        return Choice::None;
    }

    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float scale = text_scale(viewport->WorkSize.y);
    const float width = std::min(viewport->WorkSize.x * 0.9f, (page_ == Page::Main ? 320.0f : 640.0f) * scale);
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x * 0.5f,
                                   viewport->WorkPos.y + viewport->WorkSize.y * 0.5f),
                            ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, viewport->WorkSize.y * 0.92f));
    ImGui::SetNextWindowBgAlpha(0.88f);
    const char* title = page_ == Page::Main ? "Paused###menu" : page_ == Page::Settings ? "Settings###menu"
                                                                                       : "Controls###menu";
    // The main page always fits (no scroll bar); the others scroll in a small window.
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                                   (page_ == Page::Main ? ImGuiWindowFlags_NoScrollbar : 0);
    Choice choice = Choice::None;
    if (focus_first_) ImGui::SetNextWindowFocus();
    const ScaledFont scaled(scale);
    if (ImGui::Begin(title, nullptr, flags)) {
        // The Controls page focuses its first key itself (after its help line).
        if (focus_first_ && page_ != Page::Controls) {
            ImGui::SetKeyboardFocusHere();
            focus_first_ = false;
        }
        switch (page_) {
            case Page::Main: choice = draw_main(context); break;
            case Page::Settings: draw_settings(settings, context); break;
            case Page::Controls: draw_controls(settings); break;
        }
        if (page_ != Page::Main) {
            ImGui::Separator();
            if (ImGui::Button("Back", ImVec2(-1.0f, 0.0f))) {
                page_ = Page::Main;
                capture_.reset();
                focus_first_ = true;
            }
        }
    }
    ImGui::End();
    // Taps shorter than a frame were held for this one: let go of those already up.
    for (int key : tapped_) io.KeysDown[key] = context.key_down && context.key_down(key);
    tapped_.clear();
    if (choice != Choice::None) close();
    return choice;
}

PauseMenu::Choice PauseMenu::draw_main(const Context& context) {
    const ImVec2 full(-1.0f, 0.0f);
    Choice choice = Choice::None;
    if (ImGui::Button("Resume", full)) choice = Choice::Resume;
    if (ImGui::Button("Settings", full)) {
        page_ = Page::Settings;
        focus_first_ = true;
    }
    if (ImGui::Button("Controls", full)) {
        page_ = Page::Controls;
        focus_first_ = true;
        message_.clear();
    }
    if (context.can_restart && ImGui::Button("Restart the course", full)) choice = Choice::Restart;
    if (ImGui::Button("Quit", full)) choice = Choice::Quit;
    ImGui::TextDisabled("Esc: back to the game");
    return choice;
}

void PauseMenu::draw_settings(Settings& s, const Context& context) {
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    choice_combo("Quality", s.quality, kQualityChoices, quality_choice_name);
    if (s.quality == QualityChoice::Auto) {
        ImGui::SliderFloat("Auto: lowest render scale", &s.auto_min_scale, kMinAutoScale, 1.0f, "%.2f");
        ImGui::SliderFloat("Auto: highest render scale", &s.auto_max_scale, kMinAutoScale, 1.0f, "%.2f");
        // A slider past the other one pushes it along.
        s.auto_max_scale = std::max(s.auto_max_scale, s.auto_min_scale);
    }
    ImGui::Checkbox("Fullscreen", &s.window.fullscreen);
    ImGui::Checkbox("Vertical sync", &s.vsync);
    ImGui::Checkbox("Anti-aliasing (FXAA)", &s.fxaa);
    ImGui::Separator();
    percent_slider("Master volume", s.volume.master);
    percent_slider("Engine", s.volume.engine);
    percent_slider("Effects", s.volume.effects);
    percent_slider("Ambience", s.volume.ambience);
    ImGui::Separator();
    choice_combo("Camera at the start", s.camera, kViews, camera_setting_name);
    choice_combo("Wipers at the start", s.wipers, kWipers, wiper_setting_name);
    ImGui::PopItemWidth();
    if (!context.settings_error.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.35f, 1.0f), "%s", context.settings_error.c_str());
    else if (!context.settings_path.empty())
        ImGui::TextDisabled("kept in %s", context.settings_path.c_str());
    else
        ImGui::TextDisabled("not kept (no settings file in this mode)");
}

void PauseMenu::draw_controls(Settings& s) {
    ImGui::TextWrapped("Click a key (or select it and press Enter), then press the new key. Esc cancels.");
    // No scrolling of its own: the table's child window would keep keyboard and gamepad
    // navigation out (ImGui 1.86); the menu's window scrolls instead.
    const ImGuiTableFlags table_flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp;
    if (ImGui::BeginTable("controls", 4, table_flags)) {
        ImGui::TableSetupColumn("Action", 0, 2.2f);
        ImGui::TableSetupColumn("Key", 0, 1.2f);
        ImGui::TableSetupColumn("Other key", 0, 1.2f);
        ImGui::TableSetupColumn("Gamepad", 0, 1.4f);
        ImGui::TableHeadersRow();
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("Menu");
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("Esc");
        ImGui::TableNextColumn();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("Start");
        for (const ActionInfo& a : actions()) {
            ImGui::PushID(int(a.action));
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(std::string(a.label).c_str());
            for (int slot = 0; slot < KeyBindings::kSlots; ++slot) {
                ImGui::TableNextColumn();
                ImGui::PushID(slot);
                const int key = s.keys.keys(a.action)[size_t(slot)];
                const bool waiting = capture_ && capture_->action == a.action && capture_->slot == slot;
                const std::string text = waiting ? "press a key..." : key ? key_name(key) : "-";
                if (focus_first_) {
                    ImGui::SetKeyboardFocusHere();
                    focus_first_ = false;
                }
                if (ImGui::Button(text.c_str(), ImVec2(-1.0f, 0.0f)) && !capture_) {
                    capture_ = Capture{a.action, slot};
                    message_.clear();
                }
                // Right-click clears the key.
                if (key && ImGui::IsItemClicked(ImGuiMouseButton_Right)) s.keys.unbind(a.action, slot);
                ImGui::PopID();
            }
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(gamepad_name(a.action).c_str());
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
    if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
    ImGui::TextDisabled("Right-click a key to clear it.");
    if (ImGui::Button("Default keys")) {
        s.keys = KeyBindings();
        message_ = "every key back to its default";
    }
}

}  // namespace game
