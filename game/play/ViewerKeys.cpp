#include "game/play/ViewerKeys.h"

#include <GLFW/glfw3.h>

namespace game {

std::optional<ViewerKeyAction> viewer_action_for_key(int key, bool shift) {
    using A = ViewerAction;
    switch (key) {
        case GLFW_KEY_SPACE:
        case GLFW_KEY_P: return ViewerKeyAction{A::TogglePause};
        case GLFW_KEY_LEFT: return ViewerKeyAction{shift ? A::JumpBack : A::StepBack};
        case GLFW_KEY_RIGHT: return ViewerKeyAction{shift ? A::JumpForward : A::StepForward};
        case GLFW_KEY_LEFT_BRACKET:
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT: return ViewerKeyAction{A::Slower};
        case GLFW_KEY_RIGHT_BRACKET:
        case GLFW_KEY_EQUAL:  // the + key without Shift
        case GLFW_KEY_KP_ADD: return ViewerKeyAction{A::Faster};
        case GLFW_KEY_COMMA:
        case GLFW_KEY_PAGE_UP: return ViewerKeyAction{A::PreviousMarker};
        case GLFW_KEY_PERIOD:
        case GLFW_KEY_PAGE_DOWN: return ViewerKeyAction{A::NextMarker};
        case GLFW_KEY_HOME: return ViewerKeyAction{A::Start};
        case GLFW_KEY_END: return ViewerKeyAction{A::End};
        case GLFW_KEY_C: return ViewerKeyAction{A::NextCamera};
        case GLFW_KEY_H: return ViewerKeyAction{A::ToggleHud};
        case GLFW_KEY_T: return ViewerKeyAction{A::TakeOver};
        default: break;
    }
    if (key >= GLFW_KEY_1 && key < GLFW_KEY_1 + kViewerCameraModes)
        return ViewerKeyAction{A::Camera, static_cast<ViewerCameraMode>(key - GLFW_KEY_1)};
    return std::nullopt;
}

const char* viewer_keys_hint() {
    return "Space pause  Left/Right tick  Shift+Left/Right 5 s  [ ] speed  , . marker  Home/End  "
           "C or 1-5 camera  H hide  T take over";
}

}  // namespace game
