#pragma once

namespace game {

// Documented in `spindrift --help`.
enum ExitCode : int {
    kExitOk = 0,
    kExitCheckFailed = 1,  // a hash or frame check failed
    kExitUsage = 2,        // bad command line
    kExitBadInput = 3,     // a replay, level, script or image that cannot be used
    kExitPlatform = 4,     // no GL context, a shader that does not compile, no display
    kExitIo = 5,           // an output file could not be written
};

}  // namespace game
