#include "game/cli/QualityOption.h"

namespace game {

QualityChoice quality_option(const Args& args) {
    const std::optional<std::string> value = args.value("--quality");
    if (!value) return QualityChoice::Auto;
    if (std::optional<QualityChoice> choice = parse_quality_choice(*value)) return *choice;
    throw UsageError("--quality must be low, medium, high or auto, got '" + *value + "'");
}

}  // namespace game
