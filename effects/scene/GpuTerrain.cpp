#include "effects/scene/GpuTerrain.h"

#include <cstddef>
#include <optional>

#include "effects/gl/DrawCount.h"
#include "effects/scene/GpuModel.h"

namespace effects {

GpuTerrain::GpuTerrain(const TerrainMesh& mesh) : roughness_(mesh.roughness) {
    tiles_ = mesh.tiles;
    levels_.assign(tiles_.size(), 0);
    vertices_ = gl::Buffer::create<MeshVertex>("terrain.vertices", mesh.vertices, 0);
    indices_ = gl::Buffer::create<uint32_t>("terrain.indices", mesh.indices, 0);
    vao_ = mesh_vertex_array("terrain", vertices_, indices_);
}

bool GpuTerrain::plan(glm::vec3 eye, float pixels_per_radian, float max_error_px) {
    bool changed = false;
    for (size_t i = 0; i < tiles_.size(); ++i) {
        const int level = tiles_[i].level_for(eye, pixels_per_radian, max_error_px);
        changed |= levels_[i] != uint8_t(level);
        levels_[i] = uint8_t(level);
    }
    return changed;
}

void GpuTerrain::draw(const gl::Program& program, bool depth_only, const Frustum& view, bool skip_level_tiles,
                      const std::function<bool(glm::vec3, glm::vec3)>& select, const gl::Program* open_sky) const {
    vao_.bind();
    draw_tiles(program, depth_only, view, skip_level_tiles, select, &TerrainMesh::Tile::level);
    if (open_sky) open_sky->use();
    draw_tiles(open_sky ? *open_sky : program, depth_only, view, skip_level_tiles, select, &TerrainMesh::Tile::open_level);
}

void GpuTerrain::draw_tiles(const gl::Program& program, bool depth_only, const Frustum& view, bool skip_level_tiles,
                            const std::function<bool(glm::vec3, glm::vec3)>& select, Ranges ranges) const {
    if (!depth_only) {
        program.set("u_roughness", roughness_);
        program.set("u_metallic", 0.0f);
        program.set("u_emissive", glm::vec3(0.0f));
    }
    // Tiles next to each other at one level lie one after the other in the index buffer:
    // one draw for the run, its set-up paid once.
    std::optional<TerrainMesh::IndexRange> run;
    auto flush = [&] {
        if (run && run->count > 0) {
            gl::count_draw(run->count);
            glDrawElements(GL_TRIANGLES, GLsizei(run->count), GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(size_t(run->first) * sizeof(uint32_t)));
        }
        run.reset();
    };
    for (size_t i = 0; i < tiles_.size(); ++i) {
        const TerrainMesh::Tile& t = tiles_[i];
        const bool kept = !(skip_level_tiles && t.hi.y - t.lo.y < 1e-3f) && !view.outside(t.lo, t.hi) &&
                          (!select || select(t.lo, t.hi));
        if (!kept) {
            flush();
            continue;
        }
        const TerrainMesh::IndexRange r = (t.*ranges)[levels_[i]];
        if (run && run->first + run->count == r.first) {
            run->count += r.count;
            continue;
        }
        flush();
        run = r;
    }
    flush();
}

}  // namespace effects
