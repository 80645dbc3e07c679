#pragma once
// The frame loop every interactive command runs (play, replay in a window, timedemo):
// real time becomes fixed 60 Hz ticks, the renderer draws into a Screen, Dear ImGui
// draws the HUD and the debug panel on top.
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "effects/Renderer.h"
#include "effects/gl/DebugOutput.h"
#include "game/audio/LiveSound.h"
#include "game/play/DebugUi.h"
#include "game/play/GamepadInput.h"
#include "game/play/InputQueue.h"
#include "game/play/LoopViewer.h"
#include "game/play/PauseMenu.h"
#include "game/play/QualityChoice.h"
#include "game/play/ResolutionController.h"
#include "game/play/Screen.h"
#include "game/replay/CameraTrack.h"
#include "game/session/GameSession.h"
#include "game/settings/Settings.h"
#include "game/session/TickDriver.h"

namespace game {

class GhostRace;
class SettingsFile;

// Where F12 writes a screenshot taken at `when` (local time, to the millisecond):
// screenshots/spindrift_YYYYMMDD-HHMMSS-mmm.png.
std::filesystem::path screenshot_path(std::chrono::system_clock::time_point when);

// One frame the loop drew while playing (not the first one, nor idle ones).
struct FrameRecord {
    double frame_ms = 0.0;       // wall time since the previous frame was shown
    float render_scale = 1.0f;   // the 3D scene's scale it was drawn at
    int ticks = 0;               // ticks run before it
    std::chrono::nanoseconds dropped{0};  // real time the spiral cap dropped before it
};

// What drives a session: where each tick's input comes from and what happens after
// each tick and frame.
struct LoopHooks {
    // The input for the next tick, or nothing once it has run out. Unset: the keyboard.
    std::function<std::optional<sim::TickInput>()> next_input;
    // Steps the session's world and tells its listeners (recorder, checker, sound).
    TickDriver* ticks = nullptr;
    // A line for the HUD (recording state, replay progress, a desync).
    std::function<std::string()> status;
    std::function<bool()> recording;
    std::function<void(const FrameRecord&)> after_frame;  // may be unset
    // Puts the session's world back to the course's start (the menu's Restart); unset:
    // the menu has no Restart.
    std::function<void()> restart;
    // A replay viewer (game/play/ReplayViewer.h): it plays `next_input`'s ticks at its own
    // pace, takes keys first, places the camera, draws its timeline, and may hand over to
    // the keyboard. None: the clock paces the ticks.
    LoopViewer* viewer = nullptr;
};

struct LoopOptions {
    QualityChoice quality = QualityChoice::Auto;
    // A fixed render scale instead of the preset's (on auto, instead of its controller).
    std::optional<float> render_scale;
    // A game idles while its window has lost the focus; a timedemo does not.
    bool pause_when_unfocused = true;
    // Stop once the input has run out (timedemo); otherwise the last frame stays up.
    bool end_with_input = false;
    // A replay's scripted cameras (none: the player's camera throughout).
    CameraTrack cameras;
    // The player's settings for this run (the file's, with the command line's changes;
    // `quality` above wins over theirs) and the file the menu's changes go to (none:
    // they last this run only).
    Settings settings;
    SettingsFile* settings_file = nullptr;
    // The sound, paused with the game, muted by M, its volumes in the F1 panel (none: silent).
    LiveSound* sound = nullptr;
    // A replay raced beside the player (play --ghost), stepped by the ticks' listener:
    // drawn and its gaps shown (none: no ghost).
    const GhostRace* ghost = nullptr;
};

class PlayLoop {
public:
    // The screen's GL context is current. Throws std::runtime_error if the UI cannot start.
    PlayLoop(GameSession& session, Screen& screen, LoopOptions options);

    // Until the screen closes (the menu's Quit, the window's close button), or the input ends with
    // `end_with_input`.
    void run(const LoopHooks& hooks);

    void set_quality(QualityChoice quality);
    const effects::Renderer& renderer() const { return *renderer_; }
    // The UI's (HUD, text, debug panel) time at the output's size, its latest exact
    // measurement (one frame in eight).
    double ui_ms() const { return ui_ms_; }

private:
    using Clock = std::chrono::steady_clock;

    // Frames a second, over half-second spans.
    class FpsMeter {
    public:
        void frame(Clock::time_point now);
        double fps() const { return fps_; }

    private:
        Clock::time_point since_ = Clock::now();
        int frames_ = 0;
        double fps_ = 0.0;
    };

    void on_key_press(int key, bool keyboard_drives, LoopViewer* viewer);
    void on_ui_action(UiAction action);
    // Reads the gamepad: its presses act now, its axes are returned for this frame's
    // ticks (all zero without a gamepad). Returns whether a button went down.
    bool read_gamepad(bool keyboard_drives, sim::TickInput& axes);
    void draw_frame(const LoopHooks& hooks, Screen::Size size, double alpha);
    // The world's moving things now, seen from where the scripted cameras put the eye.
    effects::FramePoses poses_now(const sim::World& world) const;
    void take_screenshot(Screen::Size size);
    // The menu's (or a key's) change of the settings: applied now, and kept in the file.
    void change_settings(const Settings& after);
    // The start of a course: the settings' camera and wipers, pressed on its first ticks.
    void queue_start_presses();
    void restart(const LoopHooks& hooks);

    GameSession& session_;
    Screen& screen_;
    LoopOptions options_;
    effects::gl::DebugOutput debug_output_;  // driver errors to stderr while the context lives
    std::optional<effects::Renderer> renderer_;  // made again on a restart
    DebugUi ui_;
    Settings settings_;
    std::string settings_error_;  // the last save's failure, shown in the menu
    PauseMenu menu_;
    std::vector<sim::Control> start_presses_;  // given to the first ticks of a course
    Clock::time_point hint_until_{};  // the "Esc: menu and controls" hint fades out until then
    InputQueue input_;
    GLFWgamepadstate gamepad_before_{};  // the buttons at the last read: presses are their rising edges
    QualityChoice quality_ = QualityChoice::Auto;
    std::optional<ResolutionController> resolution_;  // auto quality only
    effects::FramePoses previous_poses_;  // the world's moving things one tick before its last
    FpsMeter fps_;
    bool paused_ = false;
    bool panel_open_ = false;
    uint64_t ui_frames_ = 0;
    double ui_ms_ = 0.0;
    bool screenshot_wanted_ = false;
    bool restart_wanted_ = false;  // the menu's Restart, done after the frame
    Clock::time_point behind_until_{};  // the HUD says "behind real time" until then
};

}  // namespace game
