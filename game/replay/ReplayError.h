#pragma once
#include <stdexcept>

namespace game {

// A replay file that cannot be read or written; the message names the file and the fault.
struct ReplayError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace game
