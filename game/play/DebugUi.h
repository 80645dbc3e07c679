#pragma once
// Dear ImGui in play mode only (headless frames stay free of UI): the HUD overlay that
// is always shown and the F1 debug panel with pass times and the renderer's params.
#include <cstdint>
#include <string>
#include <vector>

#include "effects/Renderer.h"
#include "effects/gl/PassTimer.h"
#include "effects/scene/ParamRegistry.h"
#include "sim/player/Player.h"
#include "sim/world/World.h"

struct GLFWwindow;

namespace game {

struct HudState {
    float speed_kmh = 0.0f;  // signed: negative when reversing
    sim::Vehicle vehicle = sim::Vehicle::Car;
    sim::ViewMode view = sim::ViewMode::Chase;
    sim::WiperMode wipers = sim::WiperMode::Off;
    float rain_intensity = 0.0f;  // 0..1
    uint64_t tick = 0;
    double fps = 0.0;
    bool paused = false;
    bool recording = false;
    std::string status;  // e.g. "replay ended"; empty for none
    std::vector<effects::gl::PassTime> passes;
};

// The world's part of the HUD: speed of the vehicle the player is in, view, weather, tick.
HudState hud_state(const sim::World& world);
// The HUD's text, one line each.
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

// Owns the ImGui context and its GLFW and OpenGL 3 backends for one window.
class DebugUi {
public:
    // Throws std::runtime_error if a backend fails to initialise.
    explicit DebugUi(GLFWwindow* window);
    ~DebugUi();
    DebugUi(const DebugUi&) = delete;
    DebugUi& operator=(const DebugUi&) = delete;

    // True while an ImGui widget takes typed text: game keys are not the player's then.
    bool wants_keyboard() const;

    void begin_frame();
    void draw_hud(const HudState& hud);
    // Pass times, the timing mode and every registered param; `open` is cleared by the
    // panel's close button.
    void draw_debug_panel(effects::Renderer& renderer, bool* open);
    // Draws the UI into the bound draw framebuffer.
    void end_frame();
};

}  // namespace game
