#pragma once
// `spindrift replay FILE` in a window (docs/REPLAYS.md, "The viewer"): the replay plays
// through the play loop with a timeline, pause, single ticks, speeds, jumps to markers,
// seeks, cameras and a take over. It scans the replay once at the start (its markers,
// a keyframe every five seconds, every tick's hash checked), so every seek restores a
// keyframe or a near snapshot and re-simulates the rest without rendering. Played ticks
// go through the session's TickDriver (the sound hears them, the checker checks them);
// the world is always the replay's until a take over hands the keyboard the wheel.
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

#include "game/play/LoopViewer.h"
#include "game/play/PlayLoop.h"
#include "game/play/PlayMode.h"
#include "game/play/ViewerCamera.h"
#include "game/play/ViewerKeys.h"
#include "game/replay/KeyframeStore.h"
#include "game/replay/ReplayCheck.h"
#include "game/replay/ReplayMarkers.h"
#include "game/replay/ReplaySeeker.h"
#include "game/replay/TakeOverRecording.h"
#include "game/replay/ViewerTransport.h"
#include "game/session/TickDriver.h"

namespace game {

class ReplayViewer final : public LoopViewer {
public:
    // `world` is the replay's (checked to fit it), at tick 0, stepped by `ticks`;
    // `screen` answers which keys are held (the free camera's). Scans the replay and puts
    // the world back at tick 0.
    ReplayViewer(const Replay& replay, sim::World& world, TickDriver& ticks, const Screen& screen, ViewerOptions options);

    bool key(int glfw_key) override;
    bool settle() override;
    int ticks_due(double dt_s) override;
    double alpha() const override;
    void view(effects::FramePoses& poses) override;
    void draw(Screen::Size size) override;
    bool still() const override;
    bool hud_shown() const override { return hud_shown_; }
    bool handed_over() const override { return handed_over_; }
    float covered_bottom_px() const override { return covered_bottom_px_; }

    // A key's action (what key() does once it has mapped the key).
    void act(const ViewerKeyAction& action);
    // The replay's input for the world's tick (the loop plays only ticks the viewer let due).
    std::optional<sim::TickInput> next_input() const;
    // The HUD's status line: a desync, the take over.
    std::string status() const;
    bool recording() const { return recording_; }
    uint64_t taken_at() const { return taken_at_; }  // the take over's tick

    const ReplayMarkers& markers() const { return markers_; }
    const ViewerTransport& transport() const { return transport_; }
    const ViewerCamera& camera() const { return camera_; }
    const std::optional<Divergence>& divergence() const { return divergence_; }
    size_t hashes_checked() const { return checker_.hashes_checked(); }
    // Whether a take over's recording could not be made (its file, a desync before it).
    bool take_over_failed() const { return take_over_failed_; }
    // Ends a take over's recording (renamed into place) and says where it went.
    void finish();

private:
    void take_over();
    void checked(const sim::World& world);

    const Replay& replay_;
    sim::World& world_;
    const Screen& screen_;
    ViewerOptions options_;
    KeyframeStore keyframes_;
    ReplaySeeker seeker_;
    ReplayMarkers markers_;
    ViewerTransport transport_;
    ReplayChecker checker_;
    std::optional<Divergence> divergence_;
    ViewerCamera camera_;
    sim::CameraView last_view_;     // the camera drawn last: where a free or orbit camera starts
    glm::vec3 last_vehicle_{0.0f};  // the vehicle in use as drawn last
    std::optional<uint64_t> seek_wanted_;  // from the timeline, done before the next frame's ticks
    bool camera_moving_ = false;  // a camera key held or a mouse button down at the last frame
    bool jumped_ = true;
    bool hud_shown_ = true;
    bool handed_over_ = false;
    uint64_t taken_at_ = 0;
    std::optional<TakeOverRecording> take_over_;
    bool recording_ = false;
    bool take_over_failed_ = false;
    std::chrono::steady_clock::time_point last_draw_ = std::chrono::steady_clock::now();
    float covered_bottom_px_ = 0.0f;  // the timeline's band at the screen's foot, as last drawn
};

// Watches `replay` in `session` (checked to fit it) on `screen` through the play loop
// with a ReplayViewer, until the screen closes; `loop` as for any play loop (its cameras
// the replay's). Returns an ExitCode: a desync fails the check.
int watch_replay(const Replay& replay, GameSession& session, Screen& screen, LoopOptions loop,
                 const ViewerOptions& options);

}  // namespace game
