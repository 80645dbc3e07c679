#pragma once
// Draw calls and triangles submitted to GL, as a running total for this thread's
// context: the renderer reads it around each pass (Renderer::pass_draws) to show what a
// pass sends through the CPU rasteriser's vertex and set-up stages, which on llvmpipe
// cost whatever the render scale. Counted where the geometry is drawn: the scene's
// meshes (GpuModel), the sea's lattice and the dust's shells and fins; full-screen
// triangles and particles are not counted.
#include <cstdint>

namespace effects::gl {

struct DrawCount {
    uint64_t draws = 0, triangles = 0;
};

inline DrawCount& draw_count() {
    thread_local DrawCount count;
    return count;
}

// One draw of `indices` triangle-list indices, `instances` times.
inline void count_draw(int64_t indices, int64_t instances = 1) {
    DrawCount& c = draw_count();
    ++c.draws;
    c.triangles += uint64_t(indices / 3 * instances);
}

}  // namespace effects::gl
