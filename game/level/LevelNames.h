#pragma once
// The levels a folder holds, and the one a mistyped name most likely meant.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace game {

// The level names in `dir` (its *.json files' stems), sorted; none if it cannot be read.
std::vector<std::string> level_names(const std::filesystem::path& dir);
// The name in `names` a mistyped `name` most likely meant (a few letters off, case
// ignored), if any: for "no level named 'harbor'; did you mean 'harbour'?".
std::optional<std::string> nearest_level_name(std::string_view name, const std::vector<std::string>& names);

}  // namespace game
