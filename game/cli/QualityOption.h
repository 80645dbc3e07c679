#pragma once
#include "game/cli/Args.h"
#include "game/play/QualityChoice.h"

namespace game {

// --quality low|medium|high|auto, auto when absent; anything else is a UsageError.
QualityChoice quality_option(const Args& args);

}  // namespace game
