#pragma once
#include <stdexcept>

namespace game {

// An image or EXR that could not be written or read.
struct CaptureError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace game
