#include "game/level/LevelNames.h"

#include <algorithm>

namespace game {

namespace fs = std::filesystem;

std::vector<std::string> level_names(const fs::path& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().extension() == ".json" && it->is_regular_file(ec)) names.push_back(it->path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::optional<std::string> nearest_level_name(std::string_view name, const std::vector<std::string>& names) {
    // Edit distance (insertions, deletions, substitutions), ignoring case.
    const auto distance = [](std::string_view a, std::string_view b) {
        const auto lower = [](char c) { return char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c); };
        std::vector<size_t> row(b.size() + 1);
        for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
        for (size_t i = 1; i <= a.size(); ++i) {
            size_t diagonal = row[0];
            row[0] = i;
            for (size_t j = 1; j <= b.size(); ++j) {
                const size_t above = row[j];
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1)});
                diagonal = above;
            }
        }
        return row[b.size()];
    };
    // A typo is a few letters, not a different word.
    const size_t most = std::max<size_t>(2, name.size() / 3);
    std::optional<std::string> best;
    size_t best_distance = most + 1;
    for (const std::string& candidate : names)
        if (const size_t d = distance(name, candidate); d < best_distance) {
            best = candidate;
            best_distance = d;
        }
    return best;
}

}  // namespace game
