#pragma once
// Where the sound is heard from: the presentation camera (the player's view, or a
// replay's scripted shot), and whether that camera is inside the car's cabin.
#include <glm/vec3.hpp>

namespace audio {

struct Listener {
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    bool in_cabin = false;
};

}  // namespace audio
