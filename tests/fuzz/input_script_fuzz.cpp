// The input-script parser on any text: a script that can be recorded, or one ScriptError.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "game/replay/InputScript.h"
#include "tests/fuzz/FuzzCheck.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const game::InputScript s = game::parse_script(text, "fuzz.script");
        FUZZ_CHECK(s.end_tick >= 1 && s.end_tick <= game::kMaxScriptTick);
        FUZZ_CHECK(s.inputs.size() == s.end_tick);
        FUZZ_CHECK(s.frame_width >= game::kMinFrameSide && s.frame_width <= game::kMaxFrameSide);
        FUZZ_CHECK(s.frame_height >= game::kMinFrameSide && s.frame_height <= game::kMaxFrameSide);
        FUZZ_CHECK(s.checkpoints.size() <= game::kMaxCheckpoints);
        for (size_t i = 0; i < s.checkpoints.size(); ++i) {
            FUZZ_CHECK(s.checkpoints[i] < s.end_tick);
            FUZZ_CHECK(i == 0 || s.checkpoints[i] > s.checkpoints[i - 1]);
        }
        for (const sim::TickInput& in : s.inputs) FUZZ_CHECK(sim::quantise(in) == in);
        FUZZ_CHECK(s.camera_shots.size() <= game::kMaxCameraShots);
        for (size_t i = 0; i < s.camera_shots.size(); ++i) {
            FUZZ_CHECK(s.camera_shots[i].tick < s.end_tick);
            FUZZ_CHECK(i == 0 || s.camera_shots[i].tick > s.camera_shots[i - 1].tick);
            FUZZ_CHECK(game::camera_shot_problem(s.camera_shots[i]).empty());
        }
    } catch (const game::ScriptError&) {
    }
    return 0;
}
