#pragma once
// What the frame gathers from the world once, before the passes run, for every pass that
// needs it: they receive it read-only through FrameContext::data.
#include "effects/energy/EnergyView.h"
#include "sim/world/World.h"

namespace effects {

struct FrameData {
    EnergyView energy;  // the shots in flight: the energy lights and the energy glow
};

// Fills `data` from the world. Reuses its storage.
inline void gather_frame_data(const sim::World& world, FrameData& data) { gather_energy_view(world, data.energy); }

}  // namespace effects
