#pragma once
// What the player picks with --quality or in the debug panel: one of the renderer's
// presets, or `auto`, medium with the render scale chosen by the ResolutionController.
#include <optional>
#include <string_view>

#include "effects/Quality.h"

namespace game {

enum class QualityChoice { Low, Medium, High, Auto };

inline constexpr QualityChoice kQualityChoices[] = {QualityChoice::Low, QualityChoice::Medium,
                                                    QualityChoice::High, QualityChoice::Auto};

std::string_view quality_choice_name(QualityChoice choice);
std::optional<QualityChoice> parse_quality_choice(std::string_view name);
// The preset the renderer runs: auto's is medium.
effects::Quality preset_of(QualityChoice choice);

}  // namespace game
