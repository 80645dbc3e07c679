#pragma once
// Scripted input: a small text file of timed control changes, expanded to one TickInput per
// tick. Used to record replays without a person at the keyboard.
//
//   # comment                  blank lines and '#' comments anywhere
//   level harbour              optional: the level to drive
//   frames 480x270             optional: checkpoint frame size, each side 16..4096
//   checkpoints 90 300 600     optional: ticks whose frames are checked, ascending, < end
//   0    hold throttle         from tick 0 hold these controls (replaces the held set)
//   60   hold steer=0.5 throttle=0.8   analog axes (a gamepad): throttle, brake 0..1, steer -1..1 (+ left)
//   200  tap camera            add 'camera' at tick 200 only, on top of the held set
//   300  hold                  hold nothing
//   400  camera look 10 3 -20  0 1 -30 fov=40      from the frame after 400 ticks: eye, target
//   500  camera orbit 0 1 -30  8 3 20 from=90      circle the point at radius 8 m, 3 m above it, 20 deg/s
//   600  camera follow         the player's own camera again
//   900  end                   required, last: simulate ticks 0..899
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "game/replay/CameraShot.h"
#include "game/replay/ReplayFormat.h"
#include "sim/core/TickInput.h"

namespace game {

// A script must fit in a replay.
inline constexpr uint32_t kMaxScriptTick = kMaxReplayTicks;
inline constexpr uintmax_t kMaxScriptFileBytes = 1u << 20;

struct InputScript {
    std::string level;  // empty if the script doesn't name one
    uint32_t frame_width = 480, frame_height = 270;
    std::vector<uint32_t> checkpoints;   // ascending, unique, each < end_tick
    uint32_t end_tick = 0;               // number of ticks to simulate, >= 1
    std::vector<sim::TickInput> inputs;  // expanded: inputs[t] is applied at tick t; size == end_tick
    std::vector<CameraShot> camera_shots;  // ascending ticks, each < end_tick
};

// "file:LINE: message", or "file: message" when no line is involved.
struct ScriptError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

InputScript parse_script(std::string_view text, std::string_view source_name);
InputScript load_script(const std::filesystem::path& path);

}  // namespace game
