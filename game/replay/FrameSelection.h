#pragma once
// Which ticks of a replay get rendered: its checkpoints (default), none, all, or a list.
#include <cstdint>
#include <set>
#include <string_view>

namespace game {

struct FrameSelection {
    enum class Kind { Checkpoints, None, All, List } kind = Kind::Checkpoints;
    std::set<uint32_t> ticks;  // for List

    // "all", "none", or tick numbers separated by commas; throws UsageError.
    static FrameSelection parse(std::string_view text);
    bool wants(uint32_t tick, const std::set<uint32_t>& checkpoints) const;
};

}  // namespace game
