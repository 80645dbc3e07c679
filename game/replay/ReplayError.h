#pragma once
#include <stdexcept>

namespace game {

// A replay file that cannot be read or written; the message names the file and the fault.
struct ReplayError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A recording that could not be written (no space, no permission, a vanished folder):
// the output's fault, not the input's, so the CLI exits with its I/O code.
struct ReplayWriteError : ReplayError {
    using ReplayError::ReplayError;
};

}  // namespace game
