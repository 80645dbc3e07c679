#include "game/replay/FrameSelection.h"

#include <charconv>
#include <string>

#include "game/cli/Args.h"

namespace game {

FrameSelection FrameSelection::parse(std::string_view text) {
    FrameSelection s;
    if (text == "all") {
        s.kind = Kind::All;
        return s;
    }
    if (text == "none") {
        s.kind = Kind::None;
        return s;
    }
    s.kind = Kind::List;
    while (!text.empty()) {
        size_t comma = text.find(',');
        std::string_view item = text.substr(0, comma);
        uint32_t tick = 0;
        auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), tick);
        if (item.empty() || ec != std::errc() || end != item.data() + item.size())
            throw UsageError("--frames takes 'all', 'none' or tick numbers separated by commas, got '" +
                             std::string(item) + "'");
        s.ticks.insert(tick);
        text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
    }
    if (s.ticks.empty()) throw UsageError("--frames lists no ticks");
    return s;
}

bool FrameSelection::wants(uint32_t tick, const std::set<uint32_t>& checkpoints) const {
    switch (kind) {
        case Kind::Checkpoints: return checkpoints.count(tick) != 0;
        case Kind::None: return false;
        case Kind::All: return true;
        case Kind::List: return ticks.count(tick) != 0;
    }
    return false;
}

}  // namespace game
