#pragma once
// Dear ImGui in the play loop only (replay and golden frames stay free of UI): the HUD
// overlay that is always shown and the F1 debug panel with pass times, the quality and
// the renderer's params.
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "effects/Renderer.h"
#include "effects/gl/PassTimer.h"
#include "effects/scene/ParamRegistry.h"
#include "game/play/QualityChoice.h"
#include "sim/player/Player.h"
#include "sim/world/World.h"

struct GLFWwindow;

namespace game {

// The F1 panel's window: others add their own controls to it (SoundPanel).
inline constexpr const char* kDebugPanelTitle = "Debug (F1)";

struct HudState {
    float speed_kmh = 0.0f;  // signed: negative when reversing
    sim::Vehicle vehicle = sim::Vehicle::Car;
    sim::ViewMode view = sim::ViewMode::Chase;
    sim::WiperMode wipers = sim::WiperMode::Off;
    float rain_intensity = 0.0f;  // 0..1
    uint64_t tick = 0;
    double fps = 0.0;
    bool paused = false;
    bool unfocused = false;  // idle because the window lost the keyboard focus
    bool behind = false;     // the world fell behind real time (frames too slow to keep up)
    bool recording = false;
    std::string quality;  // "auto", "low", ...; empty: no quality line
    float render_scale = 1.0f;
    int render_width = 0, render_height = 0;  // the 3D scene's internal resolution
    std::string status;  // e.g. "replay ended"; empty for none
};

// The world's part of the HUD: speed of the vehicle the player is in, view, weather, tick.
HudState hud_state(const sim::World& world);
// The HUD's text, one line each (the pass times are the debug panel's, F1, not the HUD's).
std::vector<std::string> hud_lines(const HudState& hud);

const char* vehicle_name(sim::Vehicle v);
const char* view_name(sim::ViewMode v);
const char* wiper_name(sim::WiperMode m);

// Params of one group (a pass), as indices into the registry's list, in registration order.
struct ParamGroup {
    std::string name;
    std::vector<size_t> params;
};
// Groups in the order their first param was registered.
std::vector<ParamGroup> group_params(const std::vector<effects::Param>& params);

// Owns the ImGui context and its GLFW and OpenGL 3 backends for one window, or only the
// OpenGL 3 one for an offscreen target (no window: no input, the size set each frame).
class DebugUi {
public:
    // `window` may be null. Throws std::runtime_error if a backend fails to initialise.
    explicit DebugUi(GLFWwindow* window);
    ~DebugUi();
    DebugUi(const DebugUi&) = delete;
    DebugUi& operator=(const DebugUi&) = delete;

    // True while an ImGui widget takes typed text: game keys are not the player's then.
    bool wants_keyboard() const;

    // `width` x `height`: the target's pixels (a window's backend finds its own).
    void begin_frame(int width, int height);
    void draw_hud(const HudState& hud);
    // Pass times, the timing mode, the quality and every registered param; `open` is
    // cleared by the panel's close button. Returns true when `quality` was changed.
    bool draw_debug_panel(effects::Renderer& renderer, QualityChoice& quality, bool* open);
    // Draws the UI into the bound draw framebuffer.
    void end_frame();

private:
    bool has_window_;
    std::chrono::steady_clock::time_point last_frame_ = std::chrono::steady_clock::now();
};

}  // namespace game
