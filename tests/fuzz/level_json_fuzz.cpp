// The level loader on any JSON text, read as levels/harbour.json (so valid asset names
// load the harbour's glTF files), then the world made from it as the CLI does: a level
// that runs, or one LevelError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "game/DataPaths.h"
#include "game/session/GameSession.h"
#include "tests/fuzz/FuzzCheck.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::filesystem::path file = game::data_dir() / "levels" / "harbour.json";
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        game::GameSession s = game::GameSession::start(game::load_level_text(file, text), 1);
        FUZZ_CHECK(s.level.scene.car_model >= 0 && s.level.scene.boat_model >= 0);
        for (const effects::PropInstance& p : s.level.scene.props)
            FUZZ_CHECK(p.model >= 0 && size_t(p.model) < s.level.scene.models.size());
        s.world->step(sim::TickInput{});
    } catch (const game::LevelError&) {
    }
    return 0;
}
