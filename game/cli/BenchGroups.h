#pragma once
// The groups of `spindrift bench`: what --only picks among, the help lists and the
// usage error names.
#include <array>
#include <string>
#include <string_view>

namespace game {

inline constexpr std::array<std::string_view, 11> kBenchGroups{"sim",    "replay", "water", "dust",  "fluid", "render",
                                                               "energy", "rain",   "play",  "audio", "video"};

// The groups joined with `separator`: "sim,replay,...".
inline std::string bench_groups(std::string_view separator) {
    std::string joined;
    for (std::string_view g : kBenchGroups) joined += (joined.empty() ? "" : std::string(separator)) + std::string(g);
    return joined;
}

}  // namespace game
