#include "game/session/ReplayHeaderFor.h"

namespace game {

ReplayHeader replay_header_for(const GameSession& session, uint32_t frame_width, uint32_t frame_height,
                               std::vector<uint32_t> checkpoints) {
    const sim::World& world = *session.world;
    ReplayHeader h;
    h.level_id = world.level().id;
    h.level_hash = session.level.content_hash;
    h.seed = world.level().seed;
    h.tick_rate_hz = uint32_t(sim::kTickRateHz);
    h.sim_signature = world.sim_signature();
    h.frame_width = frame_width;
    h.frame_height = frame_height;
    h.checkpoints = std::move(checkpoints);
    h.subsystem_names = world.subsystem_names();
    h.sim_params = "tick_rate_hz=" + std::to_string(sim::kTickRateHz) + " seed=" + std::to_string(h.seed);
    return h;
}

}  // namespace game
