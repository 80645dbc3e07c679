#pragma once
// The windshield drawn from inside the car: the rain's glass surface sampled on a
// grid in car model space, each vertex with its glass coordinates (metres) and the
// glass's tangents, so the height map lands exactly where the sim's drops are.
#include <cstdint>
#include <span>
#include <vector>

#include "effects/gl/Buffer.h"
#include "effects/gl/VertexArray.h"
#include "effects/rain/WindshieldCells.h"

namespace sim {
class GlassSurface;
}

namespace effects {

class WindshieldMesh {
public:
    explicit WindshieldMesh(const sim::GlassSurface& glass, int columns = 32, int rows = 12);
    // Triangles; attributes 0 position, 1 glass uv, 2 tangent u, 3 tangent v. Only the
    // cells marked in `shown` (grid().columns * rows, rows from the lower edge), each as
    // the same two triangles as in the whole mesh.
    void draw(std::span<const uint8_t> shown);
    const sim::GlassSurface* glass() const { return glass_; }
    const WindshieldCellGrid& grid() const { return grid_; }

private:
    const sim::GlassSurface* glass_;
    WindshieldCellGrid grid_;
    gl::Buffer vertices_, indices_;
    gl::VertexArray vao_;
    std::vector<GLsizei> run_counts_;  // reused each frame: one draw per run of shown cells along a row
    std::vector<const void*> run_offsets_;
};

}  // namespace effects
