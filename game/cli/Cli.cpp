#include "game/cli/Cli.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "game/capture/CaptureError.h"
#include "game/cli/Args.h"
#include "game/cli/BenchGroups.h"
#include "game/cli/Commands.h"
#include "game/cli/ExitCode.h"
#include "game/level/LevelError.h"
#include "game/play/ResolutionController.h"
#include "game/replay/InputScript.h"
#include "game/replay/ReplayError.h"

namespace game {

namespace {

// The help text; {auto_scales} stands for auto's render scales, which come from the
// resolution controller's own range, and {bench_groups} for bench's groups (help_text()).
constexpr const char* kHelp = R"(spindrift: a car-and-boat harbour game driving five real-time water and weather effects.

usage: spindrift <command> [options]

commands:
  play   [--level NAME|PATH] [--record FILE] [--quality Q] [--threads N]
         [--settings FILE] [--fullscreen|--windowed] [--ghost REPLAY]
         Drive the car, take the boat, throw, fire, in a window (Esc: the menu). With no display,
         renders the bundled demo replay headless instead and says where the frames went.
         --ghost races a replay (of the level played; default the replay's): its vehicle
         drawn see-through, stepped tick for tick beside yours, the gap at each gate shown.
  record --level NAME|PATH --script FILE --out FILE [--threads N]
         Record a replay headless from an input script (see replays/*.script).
  replay FILE [--headless] [--check] [--frames all|none|T1,T2,...] [--out DIR] [--exr]
              [--update-goldens] [--require-goldens] [--strict] [--threads N]
              [--level NAME|PATH] [--quality Q] [--settings FILE] [--audio OUT.wav]
              [--record FILE]
         Watch a replay in a window (at --quality; keys below), or play it headless. --check verifies every stored hash and
         compares the checkpoint frames with the goldens beside the replay
         (replays/NAME/tick_NNNNNN.png); failures write the actual frame and a
         difference image to --out (default spindrift-out/NAME). --frames picks the
         ticks to render (default: the checkpoints). --out writes the frames as PNG,
         --exr also as EXR (half-float HDR colour, depth, normals). --strict refuses a
         replay that was cut short. --update-goldens rewrites the goldens. A checkpoint
         with no golden yet is reported and skipped; --require-goldens fails the check.
         --audio (with --headless) renders the replay's sound offline to OUT.wav
         (48 kHz float stereo, the replay's cameras listening). --record (in a window)
         keeps a take over (T): the old inputs up to its tick, then yours.
  replay FILE --video OUT.mp4 [--from T] [--to T] [--size WxH] [--fps 30|60] [--quality CRF]
         Render the replay offline into a video: H.264 and AAC sound in MP4 (or .mov,
         .mkv), default 1280x720 at 60 fps, CRF 18 (0..51, lower is better and larger);
         --from/--to in ticks (600) or seconds (10s), default the whole replay.
  timedemo REPLAY [--size WxH] [--quality Q] [--scale S] [--json FILE] [--headless] [--threads N]
         Play a replay through play's frame loop in real time, every frame drawn with
         the HUD (a window if there is a display, else headless at --size, default
         1280x720), check its hashes, and report frames, fps, frame-time p50/p95/p99 and
         worst, per-pass means and draws, the render scale over time, game time / wall
         time and a trivial full-screen fill, every time also in fills; --scale fixes
         the render scale (0.25-1); --json writes it as JSON.
  bench  [--json FILE] [--quick] [--only {bench_groups}]
         Time the sim per subsystem, the replay check and each render pass at 1280x720
         and 640x360, and (play) the timedemo of every bundled replay at 1280x720 for
         each quality and at 1920x1080 for auto and high; prints a table and writes JSON.
  fibres IMAGE [--slices N] [--layers OUT.png]  |  fibres --draw OUT.png [--slices N]
         Dust fibre statistics (seed 004): the 26-direction growth table of a binarised
         fibre image (black fibres on white; N slices stacked vertically, one per
         layer), optionally the shell layers grown from it; --draw makes an example.

options:
  --level    a level name from levels/ (e.g. harbour) or a path to a level .json
  --threads  sim worker threads (1..64); results are identical for any count
  --quality  low, medium, high or auto (default): medium with the render scale ({auto_scales})
             lowered and raised to hold 30 ms frames
  --settings the settings file to read and keep changes in (default below)
  --fullscreen, --windowed  for this run, whatever the settings say
  --help, --version

settings: the menu's changes (quality, window, vsync, FXAA, volumes, camera and wipers
  at the start, keys) are kept in $XDG_CONFIG_HOME/spindrift/settings.json
  (~/.config/spindrift/settings.json); command-line options change them for one run only.

keys (play, by default; the menu's Controls page rebinds them): W/Up throttle, S/Down
  brake/reverse, A/D or Left/Right steer, E switch car/boat (near the pier), Backspace
  reset the vehicle onto the road or open water, 1 throw heavy, 2 throw light, Space fire,
  C camera (chase/driver), V wipers, R/F rain up/down, P pause, F12 screenshot, F1 debug
  panel (quality, pass times), F2 profile timing, F3 anti-aliasing on/off, F11 or
  Alt+Enter fullscreen, Esc the menu (resume, settings, controls, restart, quit). Every
  press counts, however slow the frames.
keys (replay in a window): Space or P pause, Left/Right one tick back/forward,
  Shift+Left/Right 5 s, [ ] or -/+ speed 0.1x-8x, , . or PageUp/PageDown the previous/next
  marker, Home/End the start/end, C or 1-5 camera (recorded, chase, driver, free fly: WASD,
  Q/E and the mouse, orbit: the mouse and the wheel), H hide the HUD and the timeline,
  T take over (drive on from this tick; see --record); click or drag the timeline to seek.
gamepad (play): right/left trigger throttle/brake, left stick steer, A switch, X throw
  heavy, Y throw light, B fire, RB camera, LB wipers, D-pad up/down rain, Start the menu,
  Back reset.

exit codes:
  0 success   1 a hash or frame check failed   2 bad command line
  3 bad input (replay, level, script, image)   4 platform (no GL context, shader, display)
  5 an output file could not be written

environment: SPINDRIFT_DATA sets the folder holding levels/ and replays/ (default: the
  installed share/spindrift beside the program, else the source tree it was built from).
)";

std::string help_text() {
    const ResolutionController::Options auto_scales;
    char range[32];
    std::snprintf(range, sizeof range, "%g..%g", double(auto_scales.min_scale), double(auto_scales.max_scale));
    std::string text = kHelp;
    const auto fill = [&text](const std::string& mark, const std::string& value) {
        text.replace(text.find(mark), mark.size(), value);
    };
    fill("{auto_scales}", range);
    fill("{bench_groups}", bench_groups(","));
    return text;
}

}  // namespace

bool display_available() {
    const char* x = std::getenv("DISPLAY");
    const char* w = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (w && *w);
}

int run_cli(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) {
        std::cerr << help_text();
        return kExitUsage;
    }
    const std::string command = args[0];
    std::vector<std::string> rest(args.begin() + 1, args.end());
    try {
        if (command == "--help" || command == "-h" || command == "help") {
            std::cout << help_text();
            return kExitOk;
        }
        if (command == "--version") {
            std::cout << "spindrift " << SPINDRIFT_VERSION << "\n";
            return kExitOk;
        }
        for (const std::string& a : rest)
            if (a == "--help" || a == "-h") {
                std::cout << help_text();
                return kExitOk;
            }
        if (command == "play") return play_command(rest);
        if (command == "record") return record_command(rest);
        if (command == "replay") return replay_command(rest);
        if (command == "bench") return bench_command(rest);
        if (command == "timedemo") return timedemo_command(rest);
        if (command == "fibres") return fibres_command(rest);
        throw UsageError("unknown command '" + command + "'");
    } catch (const UsageError& e) {
        std::cerr << "error: " << e.what() << "\n(spindrift --help lists the commands and options)\n";
        return kExitUsage;
    } catch (const ReplayWriteError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitIo;
    } catch (const ReplayError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const LevelError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const ScriptError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const CaptureError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitIo;
    } catch (const std::filesystem::filesystem_error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitIo;
    } catch (const std::exception& e) {
        // GL and platform failures: context creation, shader compilation.
        std::cerr << "error: " << e.what() << "\n";
        return kExitPlatform;
    }
}

}  // namespace game
