#pragma once
// What a level will cost in memory, estimated from the sizes it states and charged to its
// MemoryBudget before anything that size is allocated. An effect whose memory grows with
// a level's parameters adds its terms to charge_level_memory (as the water does); one
// with screen-sized targets adds its bytes per pixel to kFrameBytesPerPixel's sum.
#include <cstdint>

#include "effects/scene/SceneDesc.h"
#include "game/level/MemoryBudget.h"
#include "sim/world/LevelDesc.h"

namespace game {

// The program before any level: its code and libraries (`spindrift --version` peaks at
// 132 MiB resident).
inline constexpr uint64_t kProgramBaseBytes = 160 * kMiB;
// Rendering at all: the GL context, llvmpipe and its shader JIT, the renderer's fixed
// targets (shadow map, environment cube). A headless harbour replay check of one
// 480x270 frame peaks 100 MiB above the same check without frames.
inline constexpr uint64_t kRendererBaseBytes = 128 * kMiB;

// Every term of `level` except its assets and frames.
void charge_level_memory(const sim::LevelDesc& level, MemoryBudget& budget);

// The renderer's base, and its targets, read-back and image buffers for frames of
// width x height.
void charge_frame_memory(uint32_t width, uint32_t height, MemoryBudget& budget);

// A loaded model as the renderer keeps it: the CPU meshes and their GPU copies.
uint64_t model_memory_bytes(const effects::Model& model);

}  // namespace game
