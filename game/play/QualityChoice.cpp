#include "game/play/QualityChoice.h"

namespace game {

std::string_view quality_choice_name(QualityChoice choice) {
    switch (choice) {
        case QualityChoice::Low: return effects::quality_name(effects::Quality::Low);
        case QualityChoice::Medium: return effects::quality_name(effects::Quality::Medium);
        case QualityChoice::High: return effects::quality_name(effects::Quality::High);
        case QualityChoice::Auto: return "auto";
    }
    return "auto";
}

std::optional<QualityChoice> parse_quality_choice(std::string_view name) {
    for (QualityChoice c : kQualityChoices)
        if (name == quality_choice_name(c)) return c;
    return std::nullopt;
}

effects::Quality preset_of(QualityChoice choice) {
    switch (choice) {
        case QualityChoice::Low: return effects::Quality::Low;
        case QualityChoice::High: return effects::Quality::High;
        case QualityChoice::Medium:
        case QualityChoice::Auto: return effects::Quality::Medium;
    }
    return effects::Quality::Medium;
}

}  // namespace game
