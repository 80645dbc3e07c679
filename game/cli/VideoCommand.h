#pragma once
// spindrift replay FILE --video OUT.mp4 [--from T] [--to T] [--size WxH] [--fps 30|60]
//                       [--quality CRF] [--threads N] [--level NAME|PATH] [--strict]
#include <optional>

#include "game/cli/Args.h"

namespace game {

// The replay command's options that belong to the video export.
inline constexpr const char* kVideoOptions[] = {"--video", "--from", "--to", "--size", "--fps"};

// With --video: the export's exit code. Without: nothing (and a usage error if one of
// the export's own options is given).
std::optional<int> video_export_if_asked(const Args& args);

}  // namespace game
