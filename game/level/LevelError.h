#pragma once
#include <stdexcept>

namespace game {

// Anything wrong with a level file or one of its assets. The message names the file
// and what is wrong with it, ready to show to a person.
struct LevelError : std::runtime_error {
    using runtime_error::runtime_error;
};

}  // namespace game
