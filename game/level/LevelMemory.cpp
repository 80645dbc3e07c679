#include "game/level/LevelMemory.h"

#include <string>

namespace game {
namespace {

using std::to_string;

// Wave grid (docs/effects/water.md), per cell: the sim's two height layers, land mask,
// centre weight and damping (17 bytes), the renderer's height texture and mipmapped
// slope texture (~15 bytes) and the upload staging, rounded up.
constexpr uint64_t kWaterBytesPerCell = 48;
// Splash sheets, spray droplets and their GPU buffers: fixed by WaterParams, not the level.
constexpr uint64_t kWaterFixedBytes = 16 * kMiB;

void charge_water(const sim::LevelDesc& level, MemoryBudget& budget) {
    if (!level.water.enabled) return;
    const uint64_t side = uint64_t(level.water.size);
    budget.charge("water: wave grid " + to_string(side) + "x" + to_string(side), side * side * kWaterBytesPerCell);
    budget.charge("water: splash sheets and spray", kWaterFixedBytes);
}

// Fluid tank (docs/effects/fluid.md), per particle: the solver's state, neighbour lists
// and cached gradients, and the renderer's anisotropic kernels and instance buffers.
constexpr uint64_t kFluidBytesPerParticle = 2048;

void charge_fluid(const sim::LevelDesc& level, MemoryBudget& budget) {
    if (!level.fluid.enabled) return;
    const uint64_t n = uint64_t(level.fluid.particle_count);
    budget.charge("fluid: tank of " + to_string(n) + " particles", n * kFluidBytesPerParticle);
}

// Dust (docs/effects/dust.md): the props' amounts on their resampled meshes, the sources'
// shadow maps and the 10-layer fibre volume with its mips. The meshes are only known
// once the assets load; this bounds a warehouse's worth at the default spacing.
constexpr uint64_t kDustFixedBytes = 48 * kMiB;

void charge_dust(const sim::LevelDesc& level, MemoryBudget& budget) {
    if (level.dust.enabled) budget.charge("dust: dusty props and fibre volume", kDustFixedBytes);
}

}  // namespace

void charge_level_memory(const sim::LevelDesc& level, MemoryBudget& budget) {
    budget.charge("program base", kProgramBaseBytes);
    charge_water(level, budget);
    charge_fluid(level, budget);
    charge_dust(level, budget);
}

void charge_frame_memory(uint32_t width, uint32_t height, MemoryBudget& budget) {
    // Scene colour, normal and depth with their copies (32 bytes), the water's mask and
    // kind targets (6), the capture target, its read-back and the PNG row buffers (12),
    // and the EXR export's float read-backs and half planes (~70), rounded up.
    constexpr uint64_t kFrameBytesPerPixel = 128;
    budget.charge("renderer base", kRendererBaseBytes);
    budget.charge("frames " + to_string(width) + "x" + to_string(height),
                  uint64_t(width) * uint64_t(height) * kFrameBytesPerPixel);
}

uint64_t model_memory_bytes(const effects::Model& model) {
    uint64_t bytes = 0;
    for (const effects::MeshData& mesh : model.meshes)
        bytes += mesh.vertices.size() * sizeof(effects::MeshVertex) + mesh.indices.size() * sizeof(uint32_t);
    return 2 * bytes;  // the CPU copy and the GPU buffers
}

}  // namespace game
