#pragma once
#include <vector>

#include "game/replay/ReplayFormat.h"
#include "game/session/GameSession.h"

namespace game {

// The header of a new recording of this session's level and world.
ReplayHeader replay_header_for(const GameSession& session, uint32_t frame_width, uint32_t frame_height,
                               std::vector<uint32_t> checkpoints);

}  // namespace game
