#pragma once
// The ground (TerrainMesh) uploaded to the GPU, drawn tile by tile at a level of detail
// picked once a frame from the eye (plan): each tile at the coarsest level whose
// vertical error, seen from the eye at its nearest point, stays under a fraction of a
// scene pixel. Every pass of a frame draws the same plan, so the sun's shadow map holds
// the very surface the frame shades (no acne where a coarse tile sinks under a fine one).
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "effects/gl/Buffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/VertexArray.h"
#include "effects/scene/Frustum.h"
#include "effects/scene/TerrainMesh.h"

namespace effects {

class GpuTerrain {
public:
    explicit GpuTerrain(const TerrainMesh& mesh);

    // The level per tile for a frame seen from `eye`, `pixels_per_radian` (viewport height
    // / (2 tan(fov_y / 2))) of the frame's scene, each tile's error kept within
    // `max_error_px` pixels. Returns whether any tile's level changed.
    bool plan(glm::vec3 eye, float pixels_per_radian, float max_error_px);

    // The tiles `view` can see (and `select` keeps), at the planned levels, with the
    // material uniforms unless depth_only; with `skip_level_tiles`, not those flat and
    // level (they shade nothing: the sun's shadow casters). The triangles open to the sky
    // (split_open_sky) go after the others, through `open_sky` if given (the ground's
    // program without the sky-occlusion lookup, its uniforms set as `program`'s).
    void draw(const gl::Program& program, bool depth_only, const Frustum& view, bool skip_level_tiles,
              const std::function<bool(glm::vec3, glm::vec3)>& select = {},
              const gl::Program* open_sky = nullptr) const;

private:
    using Ranges = std::array<TerrainMesh::IndexRange, TerrainMesh::kLevels> TerrainMesh::Tile::*;
    // The tiles kept as draw() says, their triangles in `ranges` (Tile::level or open_level).
    void draw_tiles(const gl::Program& program, bool depth_only, const Frustum& view, bool skip_level_tiles,
                    const std::function<bool(glm::vec3, glm::vec3)>& select, Ranges ranges) const;

    std::vector<TerrainMesh::Tile> tiles_;
    std::vector<uint8_t> levels_;
    float roughness_;
    gl::Buffer vertices_, indices_;
    gl::VertexArray vao_;
};

}  // namespace effects
