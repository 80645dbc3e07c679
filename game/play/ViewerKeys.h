#pragma once
// The replay viewer's keys (docs/REPLAYS.md, "The viewer"): what each press does to the
// playback, the camera or the HUD. Fixed, not rebindable: the player's bindings drive the
// world, these watch it (and drive it again after a take over, when they stop). No GL:
// the viewer passes GLFW key codes, tests pass them too.
#include <optional>

#include "game/play/ViewerCamera.h"

namespace game {

enum class ViewerAction {
    TogglePause,
    StepBack,      // one tick (pauses)
    StepForward,
    JumpBack,      // five seconds (pauses)
    JumpForward,
    Slower,
    Faster,
    PreviousMarker,
    NextMarker,
    Start,
    End,
    NextCamera,
    Camera,  // the camera of ViewerKeyAction::camera
    ToggleHud,
    TakeOver,
};

struct ViewerKeyAction {
    ViewerAction action;
    ViewerCameraMode camera = ViewerCameraMode::Recorded;  // for ViewerAction::Camera
};

// How far JumpBack and JumpForward go.
inline constexpr double kViewerJumpSeconds = 5.0;

// The action of `glfw_key` pressed (with Shift held or not), if it has one.
std::optional<ViewerKeyAction> viewer_action_for_key(int glfw_key, bool shift);

// The keys, one line for the HUD's hint.
const char* viewer_keys_hint();

}  // namespace game
